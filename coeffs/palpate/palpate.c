/*
 * palpate.c — make demo-palpate: a probe palpating the liver's anterior
 * region (tests/region/liver_region.yaml, 80 x 80 mm) through the
 * firmware's region calls, replayed against true solves.
 *
 *   palpate SCENE OUTDIR [--rank R] [--every E] [--map N] [KEY=VALUE ...]
 *
 *   1. the scene (with the --set style overrides KEY=VALUE, e.g. the site
 *      spacing contact.0.spacing=10), its affine solver (one factorisation);
 *   2. the region's law (P = 2) and surface (p = 1 with site modes, at most
 *      rank R <= TFIT_REGION_MAX_RANK) fitted in-process at the scene's site
 *      spacing (tf_region_fit, one level), built as device models
 *      (palpate_models.c) and checked by tfit_model_check;
 *   3. the tips' script (palpate_path.c) through the firmware's calls at
 *      1 kHz on the caller's states (tfit_region_force, tfit_region_pair;
 *      the surface every 16 ticks: tfit_region_surface, _surface_pair);
 *   4. every E-th display tick in contact replayed against true solves of
 *      its proxies' sites (palpate_replay.c): the force error (% of the
 *      envelope radius) and the surface error (% of the peak displacement);
 *   5. the force map and the deformed surface at four ticks
 *      (palpate_pictures.c: OUTDIR/force_map.png, .vtk, surface.png,
 *      surface_TICK.vtk).
 *
 * Exits 1 when the force error exceeds FORCE_TARGET or the surface error
 * SURFACE_TARGET, 2 on bad usage or input.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/context.h"
#include "coeffs/palpate/palpate_pictures.h"
#include "fitting/region_fit.h"
#include "fitting/region_models.h"
#include "model/target_view.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define FORCE_TARGET 2.0   /* % of the envelope radius */
#define SURFACE_TARGET 5.0 /* % of the peak displacement */
#define MAX_TICKS 4096
#define PRESS 0.6          /* the presses' largest force, fraction of the envelope radius */

typedef struct options {
    const char *scene, *dir;
    const char *sets[16];
    size_t n_sets;
    unsigned rank, every, map;
} options;

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int parse(int argc, char **argv, options *o)
{
    *o = (options){.rank = TFIT_REGION_MAX_RANK, .every = 2, .map = 61};
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        unsigned *dst = strcmp(a, "--rank") == 0    ? &o->rank
                        : strcmp(a, "--every") == 0 ? &o->every
                        : strcmp(a, "--map") == 0   ? &o->map
                                                    : NULL;
        if (dst != NULL && v != NULL) {
            char *end;
            unsigned long x = strtoul(v, &end, 10);
            if (*end != '\0' || x == 0 || x > 4096) {
                return -1;
            }
            *dst = (unsigned)x;
            ++i;
        } else if (a[0] != '-' && o->scene == NULL) {
            o->scene = a;
        } else if (a[0] != '-' && o->dir == NULL) {
            o->dir = a;
        } else if (a[0] != '-' && strchr(a, '=') != NULL && o->n_sets < 16) {
            o->sets[o->n_sets++] = a;
        } else {
            return -1;
        }
    }
    return o->scene && o->dir && o->rank <= TFIT_REGION_MAX_RANK && o->map >= 2 ? 0 : -1;
}

/* The fit's last level as device models (region_models.h, as tissuefit
 * fit builds them), and its grid for the device's view. */
static int build(tf_ctx *ctx, const tf_problem *p, const tf_contact_region *r,
                 const tf_region_level *lv, tf_model **law, tf_model **surf, palpate_grid *g)
{
    *g = (palpate_grid){.nx = lv->nx, .ny = lv->ny, .ha = lv->h[0], .hb = lv->h[1]};
    memcpy(g->origin, r->chart.o, sizeof g->origin);
    memcpy(g->rot, r->chart.R, sizeof g->rot);
    return tf_region_level_models(ctx, p, 0, lv, "palpate_law", "palpate_surface", law, surf);
}

/* Four display frames for the pictures: instrument 1 holding at A, sliding,
 * both pressing, instrument 1 sliding beside the second. */
static void frames_of(size_t n, size_t frames[4])
{
    static const size_t ticks[4] = {495, 900, 2300, 2900};
    for (int i = 0; i < 4; ++i) {
        size_t k = ticks[i] < n ? ticks[i] : n - 1;
        frames[i] = k / PALPATE_DISPLAY_EVERY;
    }
}

static int run(tf_ctx *ctx, const options *o, tf_scene *sc)
{
    tf_problem *p = &sc->problem;
    const tf_contact_region *r = &p->contacts[0].region;
    double t0 = wall(), c0 = cpu();
    tf_solver *sv = tf_solver_create(p, NULL, ctx);
    if (sv == NULL) {
        return 1;
    }
    char tip[64];
    if (r->tip == TF_TIP_RECT) {
        snprintf(tip, sizeof tip, "rectangle %.3g x %.3g mm", r->tip_size[0], r->tip_size[1]);
    } else {
        snprintf(tip, sizeof tip, "disc of radius %.3g mm", r->tip_radius);
    }
    printf("%s: %zu nodes, %zu outputs, region %.4g x %.4g mm, tip %s; solver set-up %.1f s\n",
           p->name, p->cloud.n, p->outputs.n_nodes, r->chart.len[0], r->chart.len[1], tip,
           wall() - t0);
    tf_region_targets tg = tf_region_targets_default();
    tg.levels = 1;
    tg.max_rank = o->rank;
    tg.coupling = INFINITY; /* stated, not a target (region_fit.h) */
    tf_region_result res;
    double t1 = wall();
    if (tf_region_fit(ctx, sv, p, 0, &tg, &res) != 0) {
        tf_solver_destroy(sv);
        return 1;
    }
    const tf_region_level *lv = &res.level[res.n_levels - 1];
    printf("fit: %u x %u sites %.3g mm apart, rank %u, %.1f s; at the %u cell centres (never "
           "fitted): force %.2f %%, surface %.2f %% of the peak %.3g mm\n",
           lv->nx, lv->ny, lv->h[0], lv->rank, wall() - t1, (lv->nx - 1) * (lv->ny - 1),
           100 * lv->force, 100 * lv->surface, lv->peak);
    tf_model *law = NULL, *surf = NULL;
    palpate_models m = {.name = p->name, .R_F = p->envelope.radius, .peak = lv->peak, .n_out = p->outputs.n_nodes};
    tfit_model tl, ts;
    int rc = build(ctx, p, r, lv, &law, &surf, &m.grid);
    if (rc == 0) {
        tf_target_view(law, &tl);
        tf_target_view(surf, &ts);
        m.law = &tl;
        m.surf = &ts;
        m.law_host = law;
        tfit_status a = tfit_model_check(&tl), b = tfit_model_check(&ts);
        rc = a == TFIT_OK && b == TFIT_OK ? 0 : tf_fail(ctx, "tfit_model_check: law %d, surface %d", a, b);
    }
    /* the script's presses: at most PRESS of the envelope radius at any site
     * (the surface takes forces in the envelope's ball; the slides add
     * friction, up to mu of the normal force, and the second instrument
     * its coupling) */
    const double depth = rc == 0 ? palpate_depth(&m, PRESS, o->map) : 0;
    palpate_tick *t = malloc(MAX_TICKS * sizeof *t);
    palpate_run pr = {0};
    palpate_errors e = {0};
    size_t n = 0;
    if (rc == 0 && t == NULL) {
        rc = tf_fail(ctx, "out of memory");
    }
    if (rc == 0) {
        n = palpate_script(law, &m.grid, depth, t, MAX_TICKS);
        rc = palpate_loop(ctx, &m, t, n, &pr);
    }
    if (rc == 0) {
        printf("firmware loop: %zu ticks at 1 kHz (%.2f mm presses), states owned by the caller: "
               "median %.0f ns a tick (worst %.0f), the surface %.0f ns a frame\n",
               n, depth, pr.tick_ns, pr.tick_ns_worst, pr.frame_ns);
        rc = palpate_replay(ctx, sv, p, r, &m, t, &pr, o->every, &e);
    }
    if (rc == 0) {
        printf("replay: %zu ticks in contact (%zu with two instruments) against %zu true site "
               "solves, %.1f s: force error %.3f %% of the envelope radius (%zu clamped ticks "
               "not compared), surface error %.3f %% of the peak\n",
               e.ticks, e.pair_ticks, e.sites, e.seconds, e.force, e.skipped, e.surface);
        double lo, hi;
        size_t frames[4];
        frames_of(n, frames);
        rc = palpate_force_map(ctx, o->dir, &m, depth, o->map, t, &pr, &lo, &hi);
        if (rc == 0) {
            printf("force map: %u x %u sites, |F| %.3f .. %.3f N at a %.2f mm press: %s/force_map.png, .vtk\n",
                   o->map, o->map, lo, hi, depth, o->dir);
            rc = palpate_surfaces(ctx, o->dir, &m, p, t, &pr, frames, 4);
        }
        if (rc == 0) {
            printf("deformed surface at ticks %zu, %zu, %zu, %zu: %s/surface.png, surface_*.vtk\n",
                   frames[0] * PALPATE_DISPLAY_EVERY + 15, frames[1] * PALPATE_DISPLAY_EVERY + 15,
                   frames[2] * PALPATE_DISPLAY_EVERY + 15, frames[3] * PALPATE_DISPLAY_EVERY + 15,
                   o->dir);
        }
    }
    printf("total %.1f s (%.1f s of CPU)\n", wall() - t0, cpu() - c0);
    /* a replay that compared nothing, or no tick of two instruments, fails too */
    int bad = rc == 0 && !(e.force <= FORCE_TARGET && e.surface <= SURFACE_TARGET &&
                           e.ticks > e.skipped && e.pair_ticks > 0);
    if (rc == 0) {
        printf("%s: force %.3f %% (target %g %%), surface %.3f %% (target %g %%)\n",
               bad ? "FAILED" : "within the targets", e.force, FORCE_TARGET, e.surface,
               SURFACE_TARGET);
    }
    palpate_run_free(&pr);
    free(t);
    tf_model_free(law);
    tf_model_free(surf);
    tf_region_result_free(&res);
    tf_solver_destroy(sv);
    return rc != 0 || bad;
}

int main(int argc, char **argv)
{
    options o;
    if (parse(argc, argv, &o) != 0) {
        fprintf(stderr, "usage: palpate SCENE OUTDIR [--rank R <= %d] [--every E] [--map N] "
                        "[KEY=VALUE ...]\n", TFIT_REGION_MAX_RANK);
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *sc = tf_scene_load(&ctx, o.scene, o.sets, o.n_sets);
    if (sc == NULL) {
        fprintf(stderr, "palpate: %s\n", ctx.err);
        return 2;
    }
    if (sc->problem.n_contacts == 0 ||
        sc->problem.contacts[0].region.kind == TF_CONTACT_REGION_NONE) {
        fprintf(stderr, "palpate: %s: contact 0 is not a region\n", o.scene);
        tf_scene_free(sc);
        return 2;
    }
    int rc = run(&ctx, &o, sc);
    if (rc != 0 && ctx.err[0] != '\0') {
        fprintf(stderr, "palpate: %s\n", ctx.err);
    }
    tf_scene_free(sc);
    return rc;
}
