/*
 * cmd_solve.c — `tissuefit solve`: one load case of a scene, every node's
 * displacement to CSV (and VTU for ParaView); with a `history:` section, a
 * time series (CSV per step, ParaView .pvd + .vtu).
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/log.h"
#include "cli/cli.h"
#include "cli/cmd_args.h"
#include "report/displacement_out.h"
#include "base/log.h"
#include "base/plot.h"
#include "report/organ_pictures.h"
#include "report/time_series.h"
#include "scene/scene.h"
#include "solvers/probe.h"
#include "solvers/history_run.h"
#include "solvers/solver.h"

/* ParaView files a time series may write (each its own .vtu). */
#define MAX_VTU_STEPS 1000

static void help(FILE *out)
{
    fprintf(out,
            "usage: tissuefit solve SCENE [--force FX,FY,FZ] [--contact NAME] [--cut-progress S]\n"
            "                       [--set KEY=VALUE]... [--out FILE.csv] [--vtk FILE.vtu|.pvd]\n"
            "                       [--outputs FILE.csv] [--png FILE.png] [--png-rest FILE.png]\n"
            "                       [--exaggerate K] [--view AZ,EL]\n\n"
            "Solves the scene with its solver (solver.method; tissuefit --help lists them)\n"
            "and material law, and writes every node's displacement as CSV: header\n"
            "node,x,y,z,ux,uy,uz, mm, %%.17g.  The scene's loads always act; --force adds a\n"
            "force (N) at a contact site, spread as the site's patch says.  A nonlinear\n"
            "law is solved by Newton's method (rpim-galerkin hands it to rpim-newton);\n"
            "a law with history without a history: section gives the fully relaxed\n"
            "equilibrium.\n\n"
            "With a history: section (docs/scene-format.md) the solve follows it in time:\n"
            "the CSV then holds step,time,node,x,y,z,ux,uy,uz for every step, and --vtk\n"
            "FILE.pvd writes a ParaView time series (FILE.pvd and FILE_NNNN.vtu, at most\n"
            "%d steps); --force replaces history.force.\n\n"
            "Options:\n"
            "  --force FX,FY,FZ   force at the contact site, N\n"
            "  --cut-progress S   every cut of the scene only to the fraction S in [0, 1] of its\n"
            "                     path (0: uncut; docs/cutting.md, \"Cut progress\")\n"
            "  --contact NAME     which contact site (default: the first)\n"
            "  --set KEY=VALUE    override a scene value, e.g. geometry.grid=41,41,9\n"
            "                     (repeatable; see docs/scene-format.md)\n"
            "  -o, --out FILE     CSV file (default: standard output)\n"
            "  --vtk FILE.vtu     also write a VTK unstructured grid for ParaView\n"
            "  --outputs FILE     also write the scene's outputs (nodes, or points between\n"
            "                     nodes through the shape functions) as\n"
            "                     output,x,y,z,ux,uy,uz\n"
            "  --png FILE.png     an organ: its surface deformed by the solve (needs gnuplot)\n"
            "  --png-rest FILE.png  an organ at rest with its fixed region and contact sites;\n"
            "                       alone, on a scene nothing loads, it draws and solves nothing\n"
            "  --exaggerate K     draw displacements K times their size (default 1: to scale)\n"
            "  --view AZ,EL       camera azimuth about +z from +x and elevation, degrees\n"
            "                     (default: facing the contact site, turned 35 and raised 20)\n\n"
            "Progress and the time split go to stderr (quiet with tissuefit -q).\n"
            "Exit status: 0 ok, 1 the solve failed (Newton's method did not converge, a\n"
            "point inverted: the message names the load step, the force and the place),\n"
            "2 bad usage or a bad scene (nothing written then).\n",
            MAX_VTU_STEPS);
}

typedef struct solve_args {
    const char *scene, *out, *vtk, *contact, *outputs, *png, *png_rest;
    double force[3], exaggerate, view[2], progress;
    int has_force, has_progress;
    tf_sets sets;
} solve_args;

static int parse(tf_ctx *ctx, int argc, char **argv, solve_args *a)
{
    static const struct option opts[] = {{"force", required_argument, NULL, 'f'},
                                         {"contact", required_argument, NULL, 'c'},
                                         {"set", required_argument, NULL, 's'},
                                         {"out", required_argument, NULL, 'o'},
                                         {"vtk", required_argument, NULL, 'v'},
                                         {"outputs", required_argument, NULL, 'O'},
                                         {"png", required_argument, NULL, 'p'},
                                         {"png-rest", required_argument, NULL, 'r'},
                                         {"exaggerate", required_argument, NULL, 'x'},
                                         {"view", required_argument, NULL, 'w'},
                                         {"cut-progress", required_argument, NULL, 'P'},
                                         {0}};
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "o:", opts, NULL)) != -1) {
        switch (c) {
        case 'f':
            if (tf_parse_vec3(optarg, a->force) != 0) {
                tf_error(ctx, "solve: --force '%s' is not three numbers FX,FY,FZ (N)", optarg);
                return -1;
            }
            a->has_force = 1;
            break;
        case 'c':
            a->contact = optarg;
            break;
        case 's':
            if (tf_sets_add(&a->sets, optarg) != 0) {
                tf_error(ctx, "solve: out of memory");
                return -1;
            }
            break;
        case 'o':
            a->out = optarg;
            break;
        case 'v':
            a->vtk = optarg;
            break;
        case 'O':
            a->outputs = optarg;
            break;
        case 'p':
            a->png = optarg;
            break;
        case 'r':
            a->png_rest = optarg;
            break;
        case 'w':
            if (sscanf(optarg, "%lf,%lf", &a->view[0], &a->view[1]) != 2 ||
                !isfinite(a->view[0]) || !isfinite(a->view[1])) {
                tf_error(ctx, "solve: --view '%s' is not AZIMUTH,ELEVATION (degrees)", optarg);
                return -1;
            }
            break;
        case 'P': {
            char *end;
            a->progress = strtod(optarg, &end);
            if (*end != '\0' || end == optarg || !(a->progress >= 0 && a->progress <= 1)) {
                tf_error(ctx, "solve: --cut-progress '%s' is not a number in [0, 1]", optarg);
                return -1;
            }
            a->has_progress = 1;
            break;
        }
        case 'x': {
            char *end;
            a->exaggerate = strtod(optarg, &end);
            if (*end != '\0' || !(a->exaggerate > 0) || a->exaggerate > 1e6) {
                tf_error(ctx, "solve: --exaggerate '%s' is not a positive factor", optarg);
                return -1;
            }
            break;
        }
        default:
            tf_error(ctx, "solve: bad option '%s' (see tissuefit solve --help)", argv[optind - 1]);
            return -1;
        }
    }
    if (optind + 1 != argc) {
        tf_error(ctx, "solve: expected one scene file (see tissuefit solve --help)");
        return -1;
    }
    a->scene = argv[optind];
    return 0;
}

/* The contact site the force goes to, or -1 when there is no force. */
static int pick_contact(tf_ctx *ctx, const solve_args *a, const tf_problem *s)
{
    if (s->history.present && !a->has_force && !a->contact) {
        return s->history.contact;
    }
    if (!a->has_force && !s->history.present) {
        if (a->contact) {
            tf_error(ctx, "solve: --contact without --force");
            return -2;
        }
        if (tf_problem_unloaded(s)) {
            /* The answer would be zero everywhere: almost surely a forgotten --force. */
            tf_error(ctx,
                     "solve: %s: nothing loads the body (no --force, no loads and no "
                     "prescribed displacement in the scene): give --force FX,FY,FZ",
                     a->scene);
            return -2;
        }
        return -1;
    }
    if (s->n_contacts == 0) {
        tf_error(ctx, "solve: %s has no contact site for --force", a->scene);
        return -2;
    }
    int k = a->contact ? tf_problem_contact(s, a->contact) : s->history.present ? s->history.contact : 0;
    if (k < 0) {
        tf_error(ctx, "solve: %s has no contact site '%s'", a->scene, a->contact);
        return -2;
    }
    return k;
}

/* The displacement field for ParaView: an organ on its tetrahedra, a box
 * on its grid. */
/* Returns 0, or -1 (out of memory for the cells a cut leaves). */
static int write_vtu(FILE *fp, const tf_problem *p, const double *u)
{
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    if (m != NULL) {
        tf_report_vtu_displacements_tets(fp, p, m->tm.tet, m->tm.ntet, u);
        return 0;
    }
    return tf_report_vtu_displacements(fp, p, u);
}

/* The files go to temporaries first, so a failure leaves none of them. */
static int write_outputs(tf_ctx *ctx, const solve_args *a, const tf_problem *s, const double *u,
                         const double *at_outputs)
{
    const char *path[3] = {a->out, a->vtk, a->outputs};
    tf_afile f[3], *files[3];
    size_t n = 0;
    int rc = 0;
    for (int k = 0; k < 3 && rc == 0; ++k) {
        if (path[k] && tf_afile_open(ctx, &f[k], path[k]) != 0) {
            rc = -1;
        } else if (path[k]) {
            files[n++] = &f[k];
        }
    }
    if (rc == 0) {
        tf_report_csv_displacements(a->out ? f[0].fp : stdout, &s->cloud, NULL, 0, u);
        if (a->vtk && write_vtu(f[1].fp, s, u) != 0) {
            tf_fail(ctx, "out of memory for the VTK cells");
            rc = -1;
        }
        if (a->outputs) {
            tf_report_csv_outputs(f[2].fp, s, at_outputs);
        }
    }
    if (rc == 0) {
        rc = tf_afile_commit_all(ctx, files, n);
    } else {
        while (n > 0) { /* reverse order of opening (atomic_file.h) */
            tf_afile_abort(files[--n]);
        }
    }
    if (rc != 0 || (!a->out && fflush(stdout) != 0)) {
        tf_error(ctx, "solve: %s", rc ? ctx->err : "cannot write to standard output");
        return TF_EXIT_FAIL;
    }
    return TF_EXIT_OK;
}

/* The organ pictures (--png, --png-rest). */
static int pictures(tf_ctx *ctx, const solve_args *a, const tf_problem *s, int contact,
                    const double *u)
{
    tf_report_organ_view v = {.contact = contact < 0 ? 0 : contact, .exaggerate = a->exaggerate,
                       .azimuth = a->view[0], .elevation = a->view[1]};
    const double zero[3] = {0, 0, 0};
    if ((a->png_rest && tf_report_organ_rest_png(ctx, a->png_rest, s, &v) != 0) ||
        (a->png &&
         tf_report_organ_deformed_png(ctx, a->png, s, u, contact < 0 ? zero : a->force, &v) != 0)) {
        tf_error(ctx, "solve: %s", ctx->err);
        return TF_EXIT_FAIL;
    }
    return TF_EXIT_OK;
}

static int ends_with(const char *s, const char *tail)
{
    size_t n = strlen(s), m = strlen(tail);
    return n >= m && strcmp(s + n - m, tail) == 0;
}

/* The .vtu file of step k beside base.pvd: base_NNNN.vtu (its full path,
 * and its name relative to the .pvd). */
static void vtu_name(const char *pvd, size_t k, char *path, size_t len, const char **name)
{
    snprintf(path, len, "%.*s_%04zu.vtu", (int)(strlen(pvd) - 4), pvd, k + 1);
    const char *slash = strrchr(path, '/');
    *name = slash ? slash + 1 : path;
}

/* Every file of a time series, all or none. */
static int write_series(tf_ctx *ctx, const solve_args *a, const tf_problem *p, size_t n,
                        const double *t, const double *u)
{
    size_t nf = (a->out ? 1 : 0) + (a->vtk ? n + 1 : 0), k = 0;
    tf_afile *f = calloc(nf + 1, sizeof *f);
    char(*paths)[4200] = calloc(n + 1, sizeof *paths);
    const char **names = calloc(n + 1, sizeof *names);
    int rc = f && paths && names ? 0 : -1;
    if (rc != 0) {
        tf_fail(ctx, "out of memory");
    }
    if (rc == 0 && a->out && (rc = tf_afile_open(ctx, &f[k], a->out)) == 0) {
        tf_report_series_csv(f[k++].fp, &p->cloud, n, t, u);
    }
    for (size_t s = 0; rc == 0 && a->vtk && s < n; ++s) {
        vtu_name(a->vtk, s, paths[s], sizeof paths[s], &names[s]);
        if ((rc = tf_afile_open(ctx, &f[k], paths[s])) == 0 &&
            (rc = write_vtu(f[k++].fp, p, u + 3 * p->cloud.n * s)) != 0) {
            tf_fail(ctx, "out of memory for the VTK cells");
        }
    }
    if (rc == 0 && a->vtk && (rc = tf_afile_open(ctx, &f[k], a->vtk)) == 0) {
        tf_report_series_pvd(f[k++].fp, n, t, names);
    }
    if (rc == 0 && !a->out) {
        tf_report_series_csv(stdout, &p->cloud, n, t, u);
        rc = fflush(stdout) == 0 ? 0 : -1;
        if (rc != 0) {
            tf_fail(ctx, "cannot write to standard output");
        }
    }
    for (size_t q = 0; q < k; ++q) { /* every temporary written: rename them all */
        if (rc == 0) {
            rc = tf_afile_commit(ctx, &f[q]);
        } else {
            tf_afile_abort(&f[q]);
        }
    }
    free(f);
    free(paths);
    free(names);
    if (rc != 0) {
        tf_error(ctx, "solve: %s", ctx->err);
        return TF_EXIT_FAIL;
    }
    return TF_EXIT_OK;
}

/* --png-rest alone on a scene nothing loads: the picture, and no solve
 * (whose answer would be zero everywhere). */
static int rest_only(const solve_args *a, const tf_problem *p)
{
    return a->png_rest && !a->png && !a->out && !a->vtk && !a->outputs && !a->has_force &&
           !a->contact && !p->history.present && tf_problem_unloaded(p);
}

/* --png draws an organ deformed around a contact site, --png-rest one at
 * rest, with gnuplot. */
static int check_pictures(tf_ctx *ctx, const solve_args *a, const tf_problem *s)
{
    if (!a->png && !a->png_rest) {
        return 0;
    }
    if (tf_problem_mesh(s) == NULL) {
        tf_error(ctx, "solve: --png and --png-rest draw an organ (geometry.surface)");
        return -1;
    }
    if (a->png && s->n_contacts == 0) {
        tf_error(ctx, "solve: --png draws an organ deformed around a contact site, and %s has none",
                 a->scene);
        return -1;
    }
    if (s->history.present) {
        tf_error(ctx, "solve: --png and --png-rest draw one solve, not a history (use --vtk "
                      "FILE.pvd)");
        return -1;
    }
    if (!tf_plot_available()) {
        tf_error(ctx, "solve: --png needs gnuplot with the pngcairo terminal (gnuplot-nox)");
        return -1;
    }
    return 0;
}

/* The problem's history, step by step (solvers/history_run.h), written as
 * a time series. */
static int run_history(tf_ctx *ctx, const solve_args *a, const tf_problem *p, tf_solver *sv,
                       int contact)
{
    tf_history h = p->history;
    if (a->has_force) {
        if (h.table) {
            tf_error(ctx, "solve: %s: its history has a table of forces: no --force", a->scene);
            return TF_EXIT_USAGE;
        }
        memcpy(h.force, a->force, sizeof h.force);
    }
    tf_samples smp;
    if (tf_history_sample(&h, &smp) != 0) {
        tf_error(ctx, "solve: out of memory");
        return TF_EXIT_FAIL;
    }
    if (a->vtk && smp.n > MAX_VTU_STEPS) {
        tf_error(ctx, "solve: %zu steps: --vtk writes at most %d (raise history.dt)", smp.n,
                 MAX_VTU_STEPS);
        tf_samples_free(&smp);
        return TF_EXIT_USAGE;
    }
    size_t n3 = 3 * p->cloud.n;
    double *u = malloc(n3 * smp.n * sizeof *u);
    int rc = u ? tf_history_run(ctx, sv, contact, &smp, u) : -1;
    if (rc != 0) {
        tf_error(ctx, "solve: %s: %s", a->scene, u ? ctx->err : "out of memory");
        free(u);
        tf_samples_free(&smp);
        return TF_EXIT_FAIL;
    }
    tf_solver_report(sv);
    int out = write_series(ctx, a, p, smp.n, smp.t, u);
    free(u);
    tf_samples_free(&smp);
    return out;
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    solve_args a = {.exaggerate = 1, .view = {NAN, NAN}};
    tf_scene *s = NULL;
    if (parse(ctx, argc, argv, &a) != 0 ||
        tf_cmd_outputs(ctx, "solve", (const char *[]){a.out, a.vtk, a.outputs, a.png, a.png_rest},
                       5) != 0 ||
        (s = tf_cmd_scene(ctx, a.scene, &a.sets)) == NULL) {
        tf_sets_free(&a.sets);
        return TF_EXIT_USAGE;
    }
    tf_sets_free(&a.sets);
    if (a.has_progress && tf_cmd_cut_progress(ctx, a.scene, &s->problem, a.progress) != 0) {
        tf_scene_free(s);
        return TF_EXIT_USAGE;
    }
    const tf_problem *p = &s->problem;
    if (rest_only(&a, p)) { /* a look at the organ while its scene is being written */
        int rc = check_pictures(ctx, &a, p) != 0 ? TF_EXIT_USAGE : pictures(ctx, &a, p, -1, NULL);
        tf_scene_free(s);
        return rc;
    }
    int contact = pick_contact(ctx, &a, p);
    if (contact < -1 || check_pictures(ctx, &a, p) != 0) {
        tf_scene_free(s);
        return TF_EXIT_USAGE;
    }
    if (a.vtk && !ends_with(a.vtk, p->history.present ? ".pvd" : ".vtu")) {
        tf_error(ctx, "solve: --vtk %s: %s", a.vtk,
                 p->history.present ? "a time series is a .pvd file (with .vtu files beside it)"
                                    : "a .vtu file");
        tf_scene_free(s);
        return TF_EXIT_USAGE;
    }
    if (a.outputs && p->history.present) {
        tf_error(ctx, "solve: --outputs writes one solve's outputs, and %s has a history: its "
                      "time series is every node's (-o, --vtk FILE.pvd; from Python, "
                      "Scene.solve_history gives the outputs at every step)",
                 a.scene);
        tf_scene_free(s);
        return TF_EXIT_USAGE;
    }
    int rc = TF_EXIT_FAIL;
    tf_solver *sv = tf_solver_create(p, NULL, ctx);
    double *u = malloc(3 * p->cloud.n * sizeof *u);
    double *v = malloc(3 * p->outputs.n_nodes * sizeof *v);
    if (sv != NULL && u != NULL && v != NULL && p->history.present) {
        rc = run_history(ctx, &a, p, sv, contact);
    } else if (sv == NULL || u == NULL || v == NULL) {
        tf_error(ctx, "solve: %s: %s", a.scene, sv ? "out of memory" : ctx->err);
    } else if (tf_solver_solve(sv, contact, (const double(*)[3])a.force, 1, NULL, u) != 0) {
        tf_error(ctx, "solve: %s: %s", a.scene, ctx->err);
    } else if (a.outputs && tf_solver_probe_outputs(ctx, sv, p, u, v) != 0) {
        tf_error(ctx, "solve: %s: outputs: %s", a.scene, ctx->err);
    } else {
        tf_solver_report(sv);
        rc = write_outputs(ctx, &a, p, u, v);
        rc = rc == TF_EXIT_OK ? pictures(ctx, &a, p, contact, u) : rc;
    }
    free(u);
    free(v);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return rc;
}

const tf_command tf_cmd_solve = {
    .name = "solve",
    .summary = "solve a scene for one force and write nodal displacements (CSV, VTU)",
    .run = run,
    .help = help,
};
