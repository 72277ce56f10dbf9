/*
 * cmd_replay.c — `tissuefit replay`: checks a run of the haptic loop against
 * the full solve.  The native haptic loop (target/examples, HAPTIC_CSV)
 * logs every tick's force, status and output displacements; this command
 * solves every tick's force (one factorisation, all ticks as right-hand
 * sides) and reports the largest deviation, and draws the deformed output
 * surface at the tick of deepest indentation.
 *
 * A time-dependent solver (a Kelvin law: the header's prony model) is
 * stepped through the ticks in time instead, at the scene's fit.tick_us,
 * from rest: every tick a time step (docs/fitting.md §7.6).
 *
 * A tick whose force left the envelope is compared with the solve at the
 * force the firmware actually used: its projection onto the envelope.  A
 * rejected tick (NaN/Inf force) must have all-zero outputs.
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/cmd_args.h"
#include "base/log.h"
#include "base/plot.h"
#include "report/organ_pictures.h"
#include "report/surface_render.h"
#include "scene/scene.h"
#include "solvers/probe.h"
#include "solvers/solver.h"

#define META_COLUMNS 8 /* tick, fx, fy, fz, status, contact fx, fy, fz */

typedef struct ticks {
    size_t n, cols;
    double *v;    /* n x cols, row-major */
    size_t every; /* row i is the log's tick i * every + every - 1 */
} ticks;

/* The log's number of kept row i (--every). */
static size_t tick_of(const ticks *t, size_t i)
{
    return i * t->every + t->every - 1;
}

/* --every K: keep ticks K - 1, 2 K - 1, ... (the rows in place). */
static void keep_every(ticks *t, size_t every)
{
    size_t n = t->n / every;
    for (size_t i = 0; i < n; ++i) {
        memmove(t->v + i * t->cols, t->v + (i * every + every - 1) * t->cols,
                t->cols * sizeof *t->v);
    }
    t->n = n;
    t->every = every;
}

static void help(FILE *out)
{
    fprintf(out, "usage: tissuefit replay SCENE --ticks FILE.csv [--png FILE.png]\n"
                 "                        [--first N] [--every K] [--max-error-mm X] [--contact NAME]\n"
                 "                        [--set KEY=VALUE]...\n\n"
                 "Solves the force of every tick logged by the native haptic loop\n"
                 "(HAPTIC_CSV=FILE.csv) and prints the largest deviation of the logged\n"
                 "output displacements from the solve (mm).  Forces beyond the envelope\n"
                 "are compared at their projection onto it; rejected ticks must show zeros.\n\n"
                 "Options:\n"
                 "  --ticks FILE.csv   the haptic loop's log\n"
                 "  --png FILE.png     the deformed output surface at the deepest tick\n"
                 "  --first N          only the first N ticks (a short check of a long run)\n"
                 "  --every K          of those, only every K-th (ticks K-1, 2K-1, ...): fewer\n"
                 "                     solves over the same path; not for a time-dependent solve\n"
                 "  --max-error-mm X   fail (exit 1) when the largest deviation exceeds X mm\n"
                 "  --contact NAME     contact site (default: the scene's fit.contact)\n"
                 "  --set KEY=VALUE    override a scene value (repeatable)\n");
}

/* Reads the CSV (header line, then numbers).  Returns 0, or -1 naming the
 * file and line. */
static int read_ticks(tf_ctx *ctx, const char *path, ticks *t)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        tf_error(ctx, "replay: %s: cannot open it", path);
        return -1;
    }
    char *line = NULL;
    size_t cap = 0, lineno = 0, n_alloc = 0;
    ssize_t len;
    t->n = t->cols = 0;
    t->v = NULL;
    int rc = 0;
    while (rc == 0 && (len = getline(&line, &cap, f)) > 0) {
        if (++lineno == 1) {
            t->cols = 1;
            for (char *p = line; *p; ++p) {
                t->cols += *p == ',';
            }
            continue;
        }
        if (t->n == n_alloc) {
            n_alloc = n_alloc ? 2 * n_alloc : 1024;
            double *grown = realloc(t->v, n_alloc * t->cols * sizeof *grown);
            if (grown == NULL) {
                tf_error(ctx, "replay: out of memory");
                rc = -1;
                break;
            }
            t->v = grown;
        }
        char *p = line;
        for (size_t c = 0; c < t->cols; ++c) {
            char *end;
            t->v[t->n * t->cols + c] = strtod(p, &end);
            if (end == p || (c + 1 < t->cols && *end != ',')) {
                tf_error(ctx, "replay: %s:%zu: column %zu is not a number", path, lineno, c + 1);
                rc = -1;
                break;
            }
            p = end + 1;
        }
        t->n++;
    }
    free(line);
    fclose(f);
    if (rc == 0 && (t->n == 0 || t->cols < META_COLUMNS + 3)) {
        tf_error(ctx, "replay: %s: no ticks, or not the haptic loop's CSV", path);
        rc = -1;
    }
    return rc;
}

/* The force the firmware evaluated: the input, projected onto the ball. */
static void effective_force(const tf_envelope *e, const double *in, double f[3])
{
    double d[3], n2 = 0;
    for (int k = 0; k < 3; ++k) {
        d[k] = in[k] - e->centre[k];
        n2 += d[k] * d[k];
    }
    double scale = sqrt(n2) > e->radius ? e->radius / sqrt(n2) : 1.0;
    for (int k = 0; k < 3; ++k) {
        f[k] = e->centre[k] + scale * d[k];
    }
}

/* An output point with its rest (x, y), sorted into rows of equal y,
 * ascending x: gnuplot draws the blocks as a surface. */
typedef struct row_key {
    double x, y;
    size_t out;
} row_key;

static int by_row(const void *a, const void *b)
{
    const row_key *p = a, *q = b;
    if (p->y != q->y) {
        return p->y < q->y ? -1 : 1;
    }
    return (p->x > q->x) - (p->x < q->x);
}

/* The rest position of output j: its point, or its node. */
static const double *output_at(const tf_problem *s, const double *xyz, size_t j)
{
    const tf_outputs *o = &s->outputs;
    return o->points ? o->points + 3 * j : xyz + 3 * (size_t)o->nodes[j];
}

/* The outputs in row order, or NULL when out of memory. */
static size_t *rows_of(const tf_problem *s, const double *xyz)
{
    const size_t n = s->outputs.n_nodes;
    row_key *key = malloc((n + 1) * sizeof *key);
    size_t *order = malloc((n + 1) * sizeof *order);
    if (key == NULL || order == NULL) {
        free(key);
        free(order);
        return NULL;
    }
    for (size_t j = 0; j < n; ++j) {
        const double *x = output_at(s, xyz, j);
        key[j] = (row_key){.x = x[0], .y = x[1], .out = j};
    }
    qsort(key, n, sizeof *key, by_row);
    for (size_t j = 0; j < n; ++j) {
        order[j] = key[j].out;
    }
    free(key);
    return order;
}

/* Triangles over the outputs sorted into rows (rows_of; x holds the
 * outputs' rest positions): two per quadrilateral between equal-length
 * neighbouring rows.  Returns the count, 0 when the rows do not form a
 * grid, or -1 when out of memory. */
static long grid_triangles(const size_t *order, size_t n, const double *x, size_t **tri)
{
    size_t row = 0;
    while (row < n && x[3 * order[row] + 1] == x[3 * order[0] + 1]) {
        row++;
    }
    if (row < 2 || n % row != 0 || n / row < 2) {
        return 0;
    }
    size_t rows = n / row, nt = 2 * (row - 1) * (rows - 1);
    *tri = malloc(3 * nt * sizeof **tri);
    if (*tri == NULL) {
        return -1;
    }
    size_t *t = *tri;
    for (size_t r = 0; r + 1 < rows; ++r) {
        for (size_t i = 0; i + 1 < row; ++i) {
            size_t a = order[r * row + i], b = order[r * row + i + 1];
            size_t c = order[(r + 1) * row + i + 1], d = order[(r + 1) * row + i];
            *t++ = a, *t++ = b, *t++ = c;
            *t++ = a, *t++ = c, *t++ = d;
        }
    }
    return (long)nt;
}

/* The deformed output surface in depth order (report/surface_render.h): an
 * organ's whole surface from the nodal field u, or a box's grid of outputs
 * (nodes, or points between them) from their displacements v, with the
 * vertical exaggerated 4 times so that a dent of a few millimetres shows. */
static int draw(tf_ctx *ctx, const char *png, const tf_problem *s, const tf_solver *solver,
                const double *u, const double *v, size_t tick, const double f[3], int contact)
{
    char title[256];
    if (tf_problem_mesh(s) != NULL) {
        tf_report_organ_view ov = {.contact = contact, .exaggerate = 1, .azimuth = NAN,
                                   .elevation = NAN};
        if (tf_report_organ_deformed_png(ctx, png, s, u, f, &ov) != 0) {
            tf_error(ctx, "replay: %s", ctx->err);
            return -1;
        }
        return 0;
    }
    const double *xyz = tf_solver_coords(solver);
    const size_t n = s->outputs.n_nodes;
    size_t *order = rows_of(s, xyz), *tri = NULL;
    double *x = malloc((3 * n + 1) * sizeof *x), *uz = malloc((n + 1) * sizeof *uz);
    for (size_t j = 0; x != NULL && j < n; ++j) {
        memcpy(x + 3 * j, output_at(s, xyz, j), 3 * sizeof *x);
    }
    long nt = order && x && uz ? grid_triangles(order, n, x, &tri) : -1;
    if (nt <= 0) {
        tf_error(ctx, "replay: %s", nt < 0 ? "out of memory"
                                           : "--png draws output points that form a grid of rows");
        free(order);
        free(x);
        free(uz);
        return -1;
    }
    double lo = 0, hi = 0;
    for (size_t j = 0; j < n; ++j) {
        uz[j] = v[3 * j + 2];
        lo = fmin(lo, uz[j]);
        hi = fmax(hi, uz[j]);
    }
    snprintf(title, sizeof title,
             "deformed output surface at tick %zu, F = (%.3g, %.3g, %.3g) N (the solve; "
             "displacements to scale, vertical x4)",
             tick, f[0], f[1], f[2]);
    tf_report_render r = {.xyz = x, .u = v, .tri = tri, .ntri = (size_t)nt, .closed = 0,
                          .value = uz, .vmin = lo, .vmax = hi > lo ? hi : lo + 1e-9,
                          .palette = "rgb 33,13,10", .cblabel = "u_z (mm)", .azimuth = -125,
                          .elevation = 35, .zscale = 4, .title = title, .width = 1000,
                          .height = 750};
    int rc = tf_report_render_png(ctx, png, &r);
    if (rc != 0) {
        tf_error(ctx, "replay: %s", ctx->err);
    }
    free(order);
    free(tri);
    free(x);
    free(uz);
    return rc;
}

/* A nonlinear static solver: every distinct force of the ticks solved once,
 * in tick order, each continuing from the last distinct force's solution
 * (a tick's force differs little from the previous tick's, so Newton's
 * method starts near the answer; the solver falls back to load steps from
 * rest when the polish fails, e.g. at the jump to the envelope's edge).  A
 * tick whose force equals an earlier tick's bit for bit takes that solve.
 * *solves: the distinct forces solved.  Returns 0, or -1 with a message. */
static int solve_continued(tf_solver *solver, int contact, const double *forces, size_t n,
                           double *u, size_t *solves)
{
    const size_t dofs = 3 * tf_solver_node_count(solver);
    const double *prev = NULL;
    *solves = 0;
    for (size_t i = 0; i < n; ++i) {
        const double *f = forces + 3 * i;
        size_t same = i;
        for (size_t j = 0; j < i && same == i; ++j) {
            same = memcmp(forces + 3 * j, f, 3 * sizeof *f) == 0 ? j : i;
        }
        if (same < i) {
            memcpy(u + i * dofs, u + same * dofs, dofs * sizeof *u);
            continue;
        }
        if (tf_solver_solve(solver, contact, (const double(*)[3])f, 1, prev, u + i * dofs) != 0) {
            return -1;
        }
        prev = u + i * dofs;
        ++*solves;
    }
    return 0;
}

/* Compares every tick; fills *worst_tick, the deviation, and the deepest tick. */
static int compare(tf_ctx *ctx, const tf_problem *s, tf_solver *solver, int contact,
                   const ticks *t, double tick, const char *png, double bound)
{
    const int timed = (tf_solver_caps_of(solver) & TF_SOLVER_TIME_DEPENDENT) != 0;
    const int affine = (tf_solver_caps_of(solver) & TF_SOLVER_AFFINE) != 0;
    const size_t n_out = s->outputs.n_nodes, dofs = 3 * tf_solver_node_count(solver);
    double *forces = malloc(t->n * 3 * sizeof *forces), *u = malloc(t->n * dofs * sizeof *u);
    if (forces == NULL || u == NULL) {
        free(forces);
        free(u);
        tf_error(ctx, "replay: out of memory for %zu ticks", t->n);
        return TF_EXIT_FAIL;
    }
    for (size_t i = 0; i < t->n; ++i) {
        const double *row = t->v + i * t->cols;
        if (row[4] < 0) {
            forces[3 * i] = forces[3 * i + 1] = forces[3 * i + 2] = 0;
        } else {
            effective_force(&s->envelope, row + 1, forces + 3 * i);
        }
    }
    /* the solve's displacements at the outputs (nodes, or points between them) */
    double *v = malloc(t->n * 3 * n_out * sizeof *v);
    size_t solves = t->n;
    int rc = v == NULL ? -1
             : timed ? tf_solver_history(solver, contact, (const double(*)[3])forces, t->n, tick, u)
             : affine ? tf_solver_solve(solver, contact, (const double(*)[3])forces, t->n, NULL, u)
                      : solve_continued(solver, contact, forces, t->n, u, &solves);
    for (size_t i = 0; rc == 0 && i < t->n; ++i) {
        rc = tf_solver_probe_outputs(ctx, solver, s, u + i * dofs, v + i * 3 * n_out);
    }
    if (rc != 0) {
        tf_error(ctx, "replay: %s", v ? ctx->err : "out of memory");
        free(forces);
        free(u);
        free(v);
        return TF_EXIT_FAIL;
    }
    double worst = 0, deepest = -1, peak = 0, sum2 = 0;
    size_t worst_tick = 0, deep_tick = 0, rejected = 0, bad_zero = 0, not_finite = 0, terms = 0;
    size_t first_bad = 0;
    for (size_t i = 0; i < t->n; ++i) {
        const double *row = t->v + i * t->cols, *out = row + META_COLUMNS, *vi = v + i * 3 * n_out;
        for (size_t j = 0; j < n_out; ++j) {
            for (int k = 0; k < 3; ++k) {
                double logged = out[3 * j + (size_t)k];
                if (row[4] < 0) {
                    bad_zero += logged != 0;
                    continue;
                }
                /* A NaN compares false with any bound: counted, never
                 * silently skipped (it would hide behind a small maximum). */
                double e = fabs(logged - vi[3 * j + (size_t)k]);
                peak = fmax(peak, fabs(vi[3 * j + (size_t)k]));
                if (!isfinite(e)) {
                    first_bad = not_finite++ ? first_bad : i;
                    continue;
                }
                sum2 += e * e;
                terms++;
                if (e > worst) {
                    worst = e;
                    worst_tick = i;
                }
                if (k == 2 && -logged > deepest) {
                    deepest = -logged;
                    deep_tick = i;
                }
            }
        }
        rejected += row[4] < 0;
    }
    if (t->every > 1) {
        printf("replay: one tick in %zu of the log's first %zu: ticks %zu to %zu\n", t->every,
               t->n * t->every, tick_of(t, 0), tick_of(t, t->n - 1));
    }
    if (timed) {
        printf("replay: the solver is time-dependent: the %zu ticks time-stepped from rest at "
               "%.6g s per tick; peak displacement %.4g mm\n", t->n, tick, peak);
    }
    printf("replay: %zu ticks solved (%zu rejected by the firmware, their outputs %s); largest "
           "deviation of the firmware's %zu output points from the solve: %.3g mm (tick %zu)\n",
           t->n, rejected, bad_zero ? "NOT all zero" : "all zero", n_out, worst,
           tick_of(t, worst_tick));
    if (!affine && !timed) {
        printf("replay: the solver is nonlinear: %zu distinct forces solved, each continuing from "
               "the previous one; peak displacement %.4g mm\n", solves, peak);
    }
    if (!affine && peak > 0) {
        const double rms = terms ? sqrt(sum2 / (double)terms) : 0;
        printf("replay: that is %.3g %% of the peak displacement; RMS over the ticks' output "
               "components %.3g mm (%.3g %% of the peak)\n", 100 * worst / peak, rms,
               100 * rms / peak);
    }
    if (not_finite > 0) {
        tf_error(ctx, "replay: %zu logged outputs of accepted ticks are NaN or Inf (the first at "
                 "tick %zu): the deviation above covers only the finite ones",
                 not_finite, tick_of(t, first_bad));
    }
    if (worst > bound) {
        tf_error(ctx, "replay: the largest deviation %.3g mm (tick %zu) exceeds --max-error-mm %g",
                 worst, tick_of(t, worst_tick), bound);
    }
    rc = bad_zero || not_finite || worst > bound ? TF_EXIT_FAIL : TF_EXIT_OK;
    if (png != NULL && rc == TF_EXIT_OK) {
        rc = draw(ctx, png, s, solver, u + deep_tick * dofs, v + deep_tick * 3 * n_out,
                  tick_of(t, deep_tick),
                  forces + 3 * deep_tick, contact) == 0
                 ? TF_EXIT_OK
                 : TF_EXIT_FAIL;
        if (rc == TF_EXIT_OK) {
            printf("replay: wrote %s (deformed surface at tick %zu)\n", png, tick_of(t, deep_tick));
        }
    }
    free(forces);
    free(u);
    free(v);
    return rc;
}

/* --max-error-mm X: a positive number, the whole argument. */
static int parse_bound(const char *arg, double *x)
{
    char *end;
    *x = strtod(arg, &end);
    return end != arg && *end == '\0' && *x > 0 && isfinite(*x) ? 0 : -1;
}

/* --first N, --every K: a positive count, the whole argument. */
static int parse_count(const char *arg, size_t *n)
{
    char *end;
    unsigned long v = strtoul(arg, &end, 10);
    if (end == arg || *end != '\0' || arg[0] == '-' || v == 0) {
        return -1;
    }
    *n = (size_t)v;
    return 0;
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    static const struct option opts[] = {{"ticks", required_argument, NULL, 't'},
                                         {"png", required_argument, NULL, 'p'},
                                         {"contact", required_argument, NULL, 'c'},
                                         {"set", required_argument, NULL, 's'},
                                         {"first", required_argument, NULL, 'n'},
                                         {"every", required_argument, NULL, 'e'},
                                         {"max-error-mm", required_argument, NULL, 'm'},
                                         {0}};
    size_t first = 0, every = 1;
    double bound = INFINITY;
    const char *csv = NULL, *png = NULL, *contact_name = NULL;
    tf_sets sets = {0};
    int c, rc = TF_EXIT_USAGE;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (c == 't') {
            csv = optarg;
        } else if (c == 'p') {
            png = optarg;
        } else if (c == 'c') {
            contact_name = optarg;
        } else if (c == 's' && tf_sets_add(&sets, optarg) == 0) {
            continue;
        } else if (c == 'n' && parse_count(optarg, &first) == 0) {
            continue;
        } else if (c == 'e' && parse_count(optarg, &every) == 0) {
            continue;
        } else if (c == 'm' && parse_bound(optarg, &bound) == 0) {
            continue;
        } else {
            tf_error(ctx, "replay: bad option '%s' (see tissuefit replay --help)",
                     argv[optind - 1]);
            tf_sets_free(&sets);
            return TF_EXIT_USAGE;
        }
    }
    if (optind + 1 != argc || csv == NULL) {
        tf_error(ctx, "replay: expected one scene file and --ticks FILE.csv");
        tf_sets_free(&sets);
        return TF_EXIT_USAGE;
    }
    if (tf_cmd_outputs(ctx, "replay", &png, 1) != 0) {
        tf_sets_free(&sets);
        return TF_EXIT_USAGE;
    }
    ticks t = {.every = 1};
    tf_scene *s = tf_cmd_scene(ctx, argv[optind], &sets);
    const tf_problem *p = s ? &s->problem : NULL;
    tf_solver *solver = NULL;
    if (s == NULL || read_ticks(ctx, csv, &t) != 0) {
        /* reported */
    } else if (t.cols != META_COLUMNS + 3 * p->outputs.n_nodes) {
        tf_error(ctx, "replay: %s has %zu output points, the scene's outputs %zu", csv,
                 (t.cols - META_COLUMNS) / 3, p->outputs.n_nodes);
    } else {
        t.n = first > 0 && first < t.n ? first : t.n;
        int k = contact_name ? tf_problem_contact(p, contact_name) : s->fit.contact;
        if (k < 0) {
            tf_error(ctx, "replay: %s has no such contact site", argv[optind]);
        } else if (every > t.n) {
            tf_error(ctx, "replay: --every %zu keeps none of the %zu ticks", every, t.n);
        } else if ((solver = tf_solver_create(p, NULL, ctx)) == NULL) {
            tf_error(ctx, "replay: %s", ctx->err);
            rc = TF_EXIT_FAIL;
        } else if (every > 1 && (tf_solver_caps_of(solver) & TF_SOLVER_TIME_DEPENDENT)) {
            tf_error(ctx, "replay: --every: %s is solved in time, tick by tick; it needs every "
                          "tick", argv[optind]);
        } else {
            keep_every(&t, every);
            rc = compare(ctx, p, solver, k, &t, 1e-9 * s->fit.tick_ns, png, bound);
        }
    }
    tf_solver_destroy(solver);
    tf_scene_free(s);
    free(t.v);
    tf_sets_free(&sets);
    return rc;
}

const tf_command tf_cmd_replay = {
    .name = "replay",
    .summary = "check a haptic-loop run against true solves; draw the deformed surface",
    .run = run,
    .help = help,
};
