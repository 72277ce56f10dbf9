/*
 * cmd_fit.c — `tissuefit fit`: the product's main job.  A scene goes in; the
 * solver is built once, load cases are solved, every applicable model family
 * is fitted with cross-validated orders, and the chosen forward model and
 * the contact inverse are emitted as one generated header with golden
 * vectors (and, on request, a report with plots).  docs/fitting.md.
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "base/file_crc.h"
#include "cli/cli.h"
#include "cli/cmd_args.h"
#include "cli/cmd_fit.h"
#include "base/clock.h"
#include "emit/emit_header.h"
#include "cli/fit_physics.h"
#include "fitting/discretisation.h"
#include "fitting/pipeline.h"
#include "problem/datasheet.h"
#include "report/fit_report.h"
#include "base/log.h"
#include "base/plot.h"
#include "scene/scene.h"
#include "problem/mesh_geometry.h"
#include "tradeoff/select.h"
#include "solvers/solver.h"

static void help(FILE *out)
{
    char names[256];
    tf_family_names(TF_FAMILY_FORWARD, names, sizeof names);
    fprintf(out,
            "usage: tissuefit fit SCENE -o FILE.h [--family F] [--contact NAME]\n"
            "                     [--set KEY=VALUE]... [--report DIR] [--direct]\n"
            "                     [--budget-us X] [--max-error-mm E] [--mcu CORE@MHZ]\n"
            "                     [--reference INDEX.csv] [--discretisation-rel F,S]\n"
            "                     [--no-discretisation]\n\n"
            "Solves the scene's load cases (one factorisation), fits every model family\n"
            "with its orders chosen by k-fold cross-validation, measures each on held-out\n"
            "load cases exactly as the float32 firmware evaluates it, and writes FILE.h\n"
            "(the forward model NAME_forward and the contact inverse NAME_contact) and\n"
            "FILE_golden.h.  A contact region (contact.K.region) gives NAME_law and\n"
            "NAME_surface instead, their sites chosen by the held-out error at sites never\n"
            "fitted (docs/fitting.md).  The scene's fit: section sets the load cases and searches\n"
            "(docs/scene-format.md); --set overrides any of it, e.g. --set fit.train=200.\n\n"
            "Options:\n"
            "  -o, --out FILE.h    header to write (a lower-case C identifier + .h)\n"
            "  --family F          forward family to emit, one of: %s\n"
            "                      (default: the scene's fit.family, else nodal)\n"
            "  --contact NAME      contact site (default: fit.contact, else the first)\n"
            "  --set KEY=VALUE     override a scene value (repeatable)\n"
            "  --report DIR        also write DIR/NAME.md with PNG plots (needs gnuplot)\n"
            "  --direct            solve every training case instead of superposing the\n"
            "                      unit responses of a linear scene\n"
            "  --budget-us X       emit the most accurate forward model whose estimated\n"
            "                      time plus the contact inverse's fits X microseconds\n"
            "  --max-error-mm E    emit the cheapest forward model within E mm held-out\n"
            "                      (with --budget-us: the cheapest within both)\n"
            "  --reference F.csv   a finer solution of the same physics (CalculiX, ...):\n"
            "                      the header states the solve's error against it\n"
            "                      beside the fit's (docs/fitting.md, format there)\n"
            "  --discretisation-rel F,S  without a reference: the solve's error taken\n"
            "                      from another measurement, relative: F of the forward\n"
            "                      model's peak displacement, S of the contact site's\n"
            "                      (stated in the header as assumed, not measured)\n"
            "  --no-discretisation without either, the tool measures the solve's error\n"
            "                      itself on a coarser and a finer cloud (two finer ones\n"
            "                      when the coarser fails; docs/fitting.md); this skips\n"
            "                      it for quick iterations (the header says \"not\n"
            "                      measured\")\n"
            "  --mcu CORE@MHZ      cortex-m4f@168 (default) or cortex-m7@480, any clock\n"
            "                      These three choose among every candidate of\n"
            "                      `tissuefit sweep` (float32, the scene's outputs); when\n"
            "                      none qualifies, the message gives the best on each\n"
            "                      axis and nothing is written.\n\n"
            "Exit status: 0 ok, 1 a solve or fit failed, 2 bad usage or a scene that\n"
            "cannot be fitted (nothing is written then).\n",
            names);
}

typedef struct fit_args {
    const char *scene, *out, *family, *contact, *report, *reference;
    int direct, no_disc;
    tf_discretisation phys; /* when measured */
    int measured;           /* phys holds a measurement (a reference's or the tool's own) */
    char unmeasured[512];   /* else why not ("": no reason to state) */
    double disc_rel[2];     /* --discretisation-rel: forward, contact site; NAN: not given */
    double budget_us, max_error_mm; /* NAN when not given */
    tf_mcu mcu;
    tf_sets sets;
    double seconds_setup; /* the solver's assembly and factorisation */
    const char *warnings; /* the scene's ("" or lines), recorded in the header */
    const char *scene_notes; /* its repairs ("" or lines), recorded with them */
} fit_args;

/* A positive finite number, or -1 with a message. */
static int positive(tf_ctx *ctx, const char *opt, const char *text, double *v)
{
    char *end;
    *v = strtod(text, &end);
    if (*end != '\0' || !(*v > 0) || !isfinite(*v)) {
        tf_error(ctx, "fit: %s '%s' is not a positive number", opt, text);
        return -1;
    }
    return 0;
}

static int parse(tf_ctx *ctx, int argc, char **argv, fit_args *a)
{
    static const struct option opts[] = {
        {"out", required_argument, NULL, 'o'},    {"family", required_argument, NULL, 'f'},
        {"contact", required_argument, NULL, 'c'}, {"set", required_argument, NULL, 's'},
        {"report", required_argument, NULL, 'r'}, {"direct", no_argument, NULL, 'd'},
        {"budget-us", required_argument, NULL, 'b'}, {"max-error-mm", required_argument, NULL, 'e'},
        {"mcu", required_argument, NULL, 'm'},     {"reference", required_argument, NULL, 'p'},
        {"discretisation-rel", required_argument, NULL, 'D'},
        {"no-discretisation", no_argument, NULL, 'N'}, {0}};
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "o:", opts, NULL)) != -1) {
        switch (c) {
        case 'o':
            a->out = optarg;
            break;
        case 'f':
            a->family = optarg;
            break;
        case 'c':
            a->contact = optarg;
            break;
        case 's':
            if (tf_sets_add(&a->sets, optarg) != 0) {
                tf_error(ctx, "fit: out of memory");
                return -1;
            }
            break;
        case 'r':
            a->report = optarg;
            break;
        case 'd':
            a->direct = 1;
            break;
        case 'p':
            a->reference = optarg;
            break;
        case 'b':
            if (positive(ctx, "--budget-us", optarg, &a->budget_us) != 0) {
                return -1;
            }
            break;
        case 'e':
            if (positive(ctx, "--max-error-mm", optarg, &a->max_error_mm) != 0) {
                return -1;
            }
            break;
        case 'N':
            a->no_disc = 1;
            break;
        case 'D':
            if (sscanf(optarg, "%lf,%lf", &a->disc_rel[0], &a->disc_rel[1]) != 2 ||
                !(a->disc_rel[0] > 0 && a->disc_rel[0] < 1) ||
                !(a->disc_rel[1] > 0 && a->disc_rel[1] < 1)) {
                tf_error(ctx, "fit: --discretisation-rel '%s': two fractions in (0, 1), F,S",
                         optarg);
                return -1;
            }
            break;
        case 'm':
            if (tf_mcu_parse(ctx, optarg, &a->mcu) != 0) {
                tf_error(ctx, "fit: %s", ctx->err);
                return -1;
            }
            break;
        default:
            tf_error(ctx, "fit: bad option '%s' (see tissuefit fit --help)", argv[optind - 1]);
            return -1;
        }
    }
    if (optind + 1 != argc || a->out == NULL) {
        tf_error(ctx, "fit: expected one scene file and -o FILE.h (see tissuefit fit --help)");
        return -1;
    }
    a->scene = argv[optind];
    return 0;
}

/* The header, its golden file and the report directory can be written:
 * found out before the solve, not after it. */
static int check_outputs(tf_ctx *ctx, const fit_args *a)
{
    if (tf_emit_check_path(ctx, a->out, strlen("_forward")) != 0) {
        tf_error(ctx, "fit: %s", ctx->err);
        return -1;
    }
    return a->report ? tf_cmd_output_dir(ctx, "fit", a->report) : 0;
}

/* A contact region's fit (families with a region operation) takes the
 * scene and -o alone: the options about load cases, the choice among
 * candidates, the physics, the report and the servo budget (a tick of the
 * forward and contact models) are refused, not ignored. */
static int region_options(tf_ctx *ctx, const fit_args *a, const tf_scene *sc,
                          const tf_fit_plan *p)
{
    const char *opt = a->direct                      ? "--direct"
                      : !isnan(a->budget_us)         ? "--budget-us"
                      : !isnan(a->max_error_mm)      ? "--max-error-mm"
                      : a->reference != NULL         ? "--reference"
                      : !isnan(a->disc_rel[0])       ? "--discretisation-rel"
                      : a->report != NULL            ? "--report"
                      : p->servo_hz > 0              ? "fit.servo_hz"
                                                     : NULL;
    if (opt != NULL) {
        tf_error(ctx, "fit: %s: contact '%s' is a contact region: not yet: %s (a region's law "
                 "and surface are fitted by the site density rule, docs/fitting.md)",
                 a->scene, sc->problem.contacts[p->contact].name, opt);
        return -1;
    }
    return 0;
}

/* The plan from the scene's fit: section and the options. */
static int make_plan(tf_ctx *ctx, const fit_args *a, const tf_scene *sc, tf_fit_plan *p)
{
    const tf_problem *s = &sc->problem;
    *p = sc->fit;
    p->direct = a->direct;
    if (a->family) {
        p->family = tf_family_find(a->family);
        p->family_asked = 1;
        if (p->family == NULL || p->family->kind != TF_FAMILY_FORWARD) {
            char names[256];
            tf_family_names(TF_FAMILY_FORWARD, names, sizeof names);
            tf_error(ctx, "fit: --family '%s': the forward families are %s", a->family, names);
            return -1;
        }
    }
    if (s->n_contacts == 0) {
        tf_error(ctx, "fit: %s has no contact site: a fit needs the site where the haptic force "
                 "acts (add an entry under contact:, docs/scene-format.md)",
                 a->scene);
        return -1;
    }
    if (a->contact) {
        p->contact = tf_problem_contact(s, a->contact);
        if (p->contact < 0) {
            tf_error(ctx, "fit: %s has no contact site '%s'", a->scene, a->contact);
            return -1;
        }
    }
    if (tf_fit_plan_family_for_contact(ctx, p, s) != 0) {
        tf_error(ctx, "fit: %s: %s", a->scene, ctx->err);
        return -1;
    }
    return p->family->region != NULL ? region_options(ctx, a, sc, p) : 0;
}

/* Banner notes: what was fitted and how, with the overrides (they change the
 * result, so they belong with it). */
/* The largest displacement of the training cases against the body, and
 * whether it leaves the range of the scene's law (tf_fit_law_range). */
static int law_range(const tf_problem *s, const tf_fit_outcome *o, char *buf, size_t n)
{
    const tf_fitdata *d = &o->cases.train;
    if (d->n_cases == 0) {
        return 0; /* a contact region's fit solves sites, not load cases */
    }
    char why[320];
    double peak;
    size_t w = tf_fit_law_range(s, d, &peak, why, sizeof why);
    return snprintf(buf, n, "\n  largest displacement of the training cases: %.3g mm%s%s", peak,
                    w ? "\nWarning (the law's range): " : "", w ? why : "");
}

static void notes(const fit_args *a, const tf_problem *s, const tf_fit_plan *p,
                  const tf_fit_outcome *o, char *buf, size_t n)
{
    int k = p->family->region != NULL
                ? snprintf(buf, n,
                           "Fitted by `tissuefit fit`: contact region '%s', its sites solved and "
                           "judged at the\ncentres of their cells (docs/fitting.md, contact "
                           "regions).",
                           s->contacts[p->contact].name)
                : snprintf(buf, n,
                     "Fitted by `tissuefit fit`: %zu training and %zu held-out load cases at "
                     "contact site '%s',\n%s; orders by %u-fold cross-validation (seed %llu).",
                     p->n_train, p->n_heldout, s->contacts[p->contact].name,
                     o->cases.superposed ? "training cases superposed from unit solves"
                                         : "every training case solved directly",
                     p->folds, (unsigned long long)p->seed);
    for (size_t i = 0; i < a->sets.n && k > 0 && (size_t)k < n; ++i) {
        k += snprintf(buf + k, n - (size_t)k, "%s--set %s", i ? " " : "\nOverrides: ",
                      a->sets.item[i]);
    }
    if (k > 0 && (size_t)k < n) {
        /* the physics the models encode, checkable without the scene */
        k += snprintf(buf + k, n - (size_t)k, "\nPhysics (as solved):\n");
    }
    if (k > 0 && (size_t)k < n) {
        k += (int)tf_problem_datasheet(s, (int)p->contact, buf + k, n - (size_t)k);
    }
    if (k > 0 && (size_t)k < n) {
        k += law_range(s, o, buf + k, n - (size_t)k);
    }
    const char *w = a->warnings != NULL ? a->warnings : "";
    const char *r = a->scene_notes != NULL ? a->scene_notes : "";
    if ((w[0] != '\0' || r[0] != '\0') && k > 0 && (size_t)k < n) {
        /* what the tool warned about the scene, and what it repaired in
         * it, stays with what it made */
        char both[sizeof ((tf_scene *)0)->warnings + sizeof ((tf_scene *)0)->notes];
        snprintf(both, sizeof both, "%s%s", w, r);
        size_t len = strlen(both);
        len -= len > 0 && both[len - 1] == '\n';
        snprintf(buf + k, n - (size_t)k, "\nWarnings (the scene):\n%.*s", (int)len, both);
    }
}

/* An organ's output map (emit_header.h): the arrays are malloc'ed into m. */
static int organ_map(const tf_problem *s, const tf_model *fwd, uint32_t contact_node,
                     tf_emit_map *m)
{
    const tf_mesh_geometry *g = tf_problem_mesh(s);
    size_t n = fwd->n_out;
    const char *ext = strrchr(g->file, '.');
    int vtk = ext != NULL && (strcmp(ext, ".vtk") == 0 || strcmp(ext, ".VTK") == 0);
    uint32_t *vertex = malloc((n + 1) * sizeof *vertex);
    double *mm = malloc((3 * n + 1) * sizeof *mm), *file = malloc((3 * n + 1) * sizeof *file);
    *m = (tf_emit_map){.mesh_file = g->file, .mesh_crc32 = g->file_crc32, .n = n,
                       .vertex = vertex, .rest_mm = mm, .rest_file = file,
                       .contact_vertex = (uint32_t)g->tm.source[contact_node],
                       .reader = vtk ? "counted in the file's point order from 0 (gmsh)"
                                     : "counted from 0 in the order assimp 5 gives with "
                                       "aiProcess_JoinIdenticalVertices after\n * removing every "
                                       "attribute but positions (docs/header-format.md)"};
    if (vertex == NULL || mm == NULL || file == NULL) {
        return -1;
    }
    for (size_t j = 0; j < n; ++j) {
        size_t node = fwd->node_ids[j] - 1; /* an output of an organ is a surface vertex */
        vertex[j] = (uint32_t)g->tm.source[node];
        memcpy(mm + 3 * j, g->tm.xyz + 3 * node, 3 * sizeof *mm);
        memcpy(file + 3 * j, g->file_xyz + 3 * node, 3 * sizeof *file);
    }
    return 0;
}

static void organ_map_free(tf_emit_map *m)
{
    free((void *)m->vertex);
    free((void *)m->rest_mm);
    free((void *)m->rest_file);
}

static int emit(tf_ctx *ctx, const fit_args *a, const tf_problem *s, const tf_fit_plan *p,
                tf_fit_outcome *o, tf_model *fwd, tf_model *con, const char *choice)
{
    char base[TF_NAME_MAX - 8], note[4096];
    const char *slash = strrchr(a->out, '/');
    if (fwd == NULL || con == NULL) {
        tf_error(ctx, "fit: %s: no %s model to emit", a->scene, fwd ? "inverse" : "forward");
        return TF_EXIT_FAIL;
    }
    snprintf(base, sizeof base, "%s", slash ? slash + 1 : a->out); /* fits: check_outputs */
    base[strcspn(base, ".")] = '\0';
    const int region = p->family->region != NULL;
    snprintf(fwd->name, sizeof fwd->name, "%s_%s", base, tf_family_suffix(tf_family_of(fwd->family)));
    snprintf(con->name, sizeof con->name, "%s_%s", base, tf_family_suffix(tf_family_of(con->family)));
    if (a->measured) {
        tf_fit_physics_state(&a->phys, &s->envelope, fwd, con);
        if (region) {
            tf_fit_physics_at_centre(fwd, con);
        }
    } else if (!isnan(a->disc_rel[0])) {
        if (tf_fit_physics_assume(ctx, a->disc_rel, &s->envelope, fwd, con) != 0) {
            return TF_EXIT_USAGE;
        }
    } else if (a->unmeasured[0] != '\0') {
        tf_fit_physics_unmeasured(a->unmeasured, !region, fwd, con);
    }
    uint32_t crc = 0;
    if (tf_file_crc32(a->scene, &crc) != 0) {
        tf_error(ctx, "fit: %s: cannot read it again for its checksum", a->scene);
        return TF_EXIT_FAIL;
    }
    notes(a, s, p, o, note, sizeof note);
    if (choice != NULL) {
        size_t k = strlen(note);
        snprintf(note + k, sizeof note - k, "\n%s", choice);
    }
    const tf_contact *site = &s->contacts[p->contact];
    tf_emit_map map = {0};
    /* An organ's outputs that are surface vertices get the vertex map; points
     * (select: points) are named by their positions like a box's. */
    int organ = tf_problem_mesh(s) != NULL && s->outputs.points == NULL;
    if (organ && organ_map(s, fwd, site->node, &map) != 0) {
        organ_map_free(&map);
        tf_error(ctx, "fit: out of memory");
        return TF_EXIT_FAIL;
    }
    const tf_emit_info info = {.source = a->scene, .has_source_crc = 1, .source_crc32 = crc,
                               .notes = note, .golden_seed = p->seed,
                               .map = organ ? &map : NULL,
                               .servo_hz = p->servo_hz, /* 0 for a region: region_options */
                               .points = s->outputs.points, .n_points = s->outputs.n_nodes,
                               .contact_point = site->by_node || region ? NULL : site->at};
    tf_model *models[2] = {fwd, con};
    int rc = tf_emit_header(ctx, a->out, models, 2, &info);
    organ_map_free(&map);
    if (rc != 0) {
        tf_error(ctx, "fit: %s", ctx->err); /* the path was checked: a failure while running */
        return TF_EXIT_FAIL;
    }
    tf_info(ctx, "fit: wrote %s (%s %s, %s %s) and its golden vectors", a->out,
            tf_family_of(fwd->family)->name, region ? "surface" : "forward model",
            tf_family_of(con->family)->name, region ? "law" : "contact inverse");
    return TF_EXIT_OK;
}

/* --budget-us / --max-error-mm: the sweep's candidates, then the choice. */
static int emit_selected(tf_ctx *ctx, const fit_args *a, const tf_problem *s, tf_solver *solver,
                         const tf_fit_plan *p, tf_fit_outcome *o)
{
    char choice[1280]; /* every part at its longest: -Wformat-truncation */
    tf_sweep sw;
    tf_selection sel;
    tf_info(ctx, "fit: measuring every candidate for the choice (tissuefit sweep)");
    if (tf_sweep_run(ctx, s, solver, p, 1u << TF_SET_SCENE, &sw) != 0) {
        tf_error(ctx, "fit: %s", ctx->err);
        return TF_EXIT_FAIL;
    }
    /* the contact inverse: within 1e-4 of the envelope radius (the issue's
     * bound for linear scenes), else the most accurate passive one */
    const double disc = a->measured ? a->phys.max_mm : NAN;
    if (tf_select(ctx, &sw, &a->mcu, a->budget_us, a->max_error_mm, disc,
                  1e-4 * s->envelope.radius, &sel) != 0) {
        tf_error(ctx, "fit: %s: %s; nothing written", a->scene, ctx->err);
        tf_sweep_free(&sw);
        return TF_EXIT_USAGE;
    }
    char limits[128] = "";
    if (!isnan(a->budget_us)) {
        snprintf(limits, sizeof limits, "a budget of %.4g us", a->budget_us);
    }
    if (!isnan(a->max_error_mm)) {
        size_t k = strlen(limits);
        snprintf(limits + k, sizeof limits - k, "%sa total error <= %.3g mm", k ? " and " : "",
                 a->max_error_mm);
    }
    char how_far[256];
    const tf_candidate *f = sel.forward;
    const double total = tf_select_total(f, disc);
    if (isnan(disc)) {
        snprintf(how_far, sizeof how_far,
                 "held-out max %.3g mm, %.3g %% of the %.3g mm its held-out cases reach; the "
                 "discretisation not measured (%.120s)",
                 f->heldout_max, 100 * f->heldout_max / f->peak, f->peak,
                 a->unmeasured[0] ? a->unmeasured : "no --reference");
    } else {
        snprintf(how_far, sizeof how_far,
                 "held-out max %.3g mm + discretisation %.3g mm = total %.3g mm, %.3g %% of the "
                 "%.3g mm its held-out cases reach",
                 f->heldout_max, disc, total, 100 * total / f->peak, f->peak);
    }
    char contact_note[160] = "";
    if (!sel.contact_within_tol) {
        snprintf(contact_note, sizeof contact_note,
                 ", the most accurate passive one (held-out %.3g N; none within %.3g N)",
                 sel.contact->heldout_max, 1e-4 * s->envelope.radius);
    }
    snprintf(choice, sizeof choice,
             "Chosen among every candidate for %s on %s: %s (%.2f us; %s) and the contact "
             "inverse %s (%.2f us%s).",
             limits, a->mcu.name, f->label, tf_candidate_us(f, &a->mcu), how_far,
             sel.contact->label, tf_candidate_us(sel.contact, &a->mcu), contact_note);
    tf_info(ctx, "fit: %s", choice);
    int rc = emit(ctx, a, s, p, o, sel.forward->model, sel.contact->model, choice);
    tf_sweep_free(&sw);
    return rc;
}

/* The checksum every rank of an MPI run must agree on: the scene file's
 * bytes and the overrides. */
static uint32_t fingerprint(const fit_args *a)
{
    uint32_t crc = 0;
    if (tf_file_crc32(a->scene, &crc) != 0) {
        return 0;
    }
    uLong c = crc;
    for (size_t i = 0; i < a->sets.n; ++i) {
        c = crc32(c, (const Bytef *)a->sets.item[i], (uInt)strlen(a->sets.item[i]) + 1);
    }
    return (uint32_t)c;
}

/* The command line, the scene, the plan and the solver: 0 when all are
 * ready, else the exit status after the message. */
static int prepare(tf_ctx *ctx, int argc, char **argv, fit_args *a, tf_scene **s,
                   tf_fit_plan *plan, tf_solver **solver)
{
    if (parse(ctx, argc, argv, a) != 0 || check_outputs(ctx, a) != 0 ||
        (*s = tf_cmd_scene(ctx, a->scene, &a->sets)) == NULL || make_plan(ctx, a, *s, plan) != 0) {
        return TF_EXIT_USAGE;
    }
    a->warnings = (*s)->warnings;
    a->scene_notes = (*s)->notes;
    if (a->report && !tf_plot_available()) {
        tf_error(ctx,
                 "fit: --report needs gnuplot with the pngcairo terminal (Debian: gnuplot-nox)");
        return TF_EXIT_USAGE;
    }
    const double t0 = tf_seconds();
    *solver = tf_solver_create(&(*s)->problem, NULL, ctx);
    a->seconds_setup = tf_seconds() - t0;
    if (*solver == NULL) {
        tf_error(ctx, "fit: %s", ctx->err);
        return TF_EXIT_FAIL;
    }
    return TF_EXIT_OK;
}

/* Where the time to regenerate a header goes (make bench-regen reads this
 * line): the solver's setup (assembly, factorisation), the load cases'
 * solves, the families' fits (orders, held-out errors), and the rest
 * (selection sweep, golden vectors, writing). */
static void time_split(const tf_ctx *ctx, const fit_args *a, const tf_fit_outcome *o,
                       double total)
{
    double fits = 0;
    for (size_t i = 0; i < o->n_families; ++i) {
        fits += o->fam[i].seconds;
    }
    tf_info(ctx, "fit: time: setup %.3f s, solves %.3f s, fits %.3f s, header %.3f s", a->seconds_setup,
            o->seconds_cases, fits, total - o->seconds_cases - fits);
}

/* The fit, the header and the report. */
static int fit(tf_ctx *ctx, fit_args *a, const tf_problem *p, tf_solver *solver,
               const tf_fit_plan *plan)
{
    if (a->reference != NULL) {
        tf_info(ctx, "fit: the solve against the physics: %s", a->reference);
        if (tf_discretisation_measure(ctx, solver, p, plan->contact, a->reference, &a->phys) != 0) {
            tf_error(ctx, "fit: --reference %s", ctx->err);
            return TF_EXIT_USAGE;
        }
        tf_info(ctx, "fit: discretisation: max %.3g mm (%s), contact site %.3g %%", a->phys.max_mm,
                a->phys.enveloped ? "over the envelope" : "over the cases", 100 * a->phys.site_rel);
        a->measured = 1;
    } else if (a->no_disc) {
        snprintf(a->unmeasured, sizeof a->unmeasured, "--no-discretisation");
    }
    tf_fit_outcome o;
    double t0 = tf_seconds();
    int fitted = tf_fit_run(ctx, p, solver, plan, &o);
    if (fitted != 0) {
        tf_error(ctx, "fit: %s: %s", a->scene, ctx->err);
        return fitted == -2 ? TF_EXIT_USAGE : TF_EXIT_FAIL;
    }
    /* After the fit, so that a scene the fit refuses costs no extra
     * clouds; before the choice, which counts it.  A region's contact
     * carries the probe's patch at the region's centre
     * (scene_contact_region.c): measured at that site. */
    if (a->reference == NULL && !a->no_disc && isnan(a->disc_rel[0])) {
        const double t_self = tf_seconds();
        if (tf_fit_physics_self(ctx, a->scene, &a->sets, solver, p, plan->contact, &a->phys) == 0) {
            a->measured = 1;
        } else {
            snprintf(a->unmeasured, sizeof a->unmeasured, "%.400s", ctx->err);
            tf_warn(ctx, "fit: the discretisation not measured: %s", ctx->err);
        }
        t0 += tf_seconds() - t_self; /* not the header's time (it states its own) */
    }
    int rc;
    if (isnan(a->budget_us) && isnan(a->max_error_mm)) {
        rc = emit(ctx, a, p, plan, &o, tf_fit_emitted(&o, plan, TF_FAMILY_FORWARD),
                  tf_fit_emitted(&o, plan, TF_FAMILY_INVERSE), NULL);
    } else {
        rc = emit_selected(ctx, a, p, solver, plan, &o);
    }
    if (rc == TF_EXIT_OK) {
        time_split(ctx, a, &o, tf_seconds() - t0);
    }
    if (rc == TF_EXIT_OK && a->report &&
        tf_report_fit(ctx, a->report, a->out, p, solver, plan, &o) != 0) {
        tf_error(ctx, "fit: report: %s", ctx->err);
        rc = TF_EXIT_FAIL;
    }
    tf_fit_outcome_free(&o);
    return rc;
}

int tf_cmd_fit_ranks(tf_ctx *ctx, int argc, char **argv, const tf_fit_ranks *ranks)
{
    fit_args a = {.budget_us = NAN, .max_error_mm = NAN, .disc_rel = {NAN, NAN}};
    tf_scene *s = NULL;
    tf_solver *solver = NULL;
    tf_fit_plan plan;
    tf_mcu_parse(ctx, "cortex-m4f@168", &a.mcu);
    int rc = prepare(ctx, argc, argv, &a, &s, &plan, &solver);
    if (ranks != NULL) {
        rc = ranks->agree(ranks->user, ctx, rc, rc == TF_EXIT_OK ? fingerprint(&a) : 0);
        if (rc == TF_EXIT_OK && ranks->worker) {
            rc = ranks->serve(ranks->user, solver);
        } else if (rc == TF_EXIT_OK) {
            plan.runner = ranks->runner;
            rc = fit(ctx, &a, &s->problem, solver, &plan);
            ranks->stop(ranks->user);
        }
    } else if (rc == TF_EXIT_OK) {
        rc = fit(ctx, &a, &s->problem, solver, &plan);
    }
    tf_solver_destroy(solver);
    tf_scene_free(s);
    tf_sets_free(&a.sets);
    return rc;
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    return tf_cmd_fit_ranks(ctx, argc, argv, NULL);
}

const tf_command tf_cmd_fit = {
    .name = "fit",
    .summary = "fit a scene's models and write the generated header (the main job)",
    .run = run,
    .help = help,
};
