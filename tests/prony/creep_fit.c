/*
 * creep_fit.c — issue 14 acceptance 2, the held-out part, on synthetic
 * histories: block48 (tests/solver/block48_seed.yaml, its static solves) as a linear
 * viscoelastic body with a constant Poisson ratio, whose response to a
 * force history is the relaxed static response of the force filtered by
 * the creep function (exact by the correspondence principle; integrated in
 * continuous time, histories.h).  The prony family fits its order search
 * on the training histories; the float32 model is stepped through held-out
 * press-hold-release histories it never saw; the largest error over every
 * output and tick must stay within MAX_REL of the largest displacement.
 * Writes the model as a header for the device checks.
 *
 *   creep_fit SCENE CREEP OUT.h MAX_REL
 *     CREEP  kelvin:K1,K2,ETA   seed 001's Kelvin solid (MPa, MPa, MPa s)
 *            two:W1,TAU1,W2,TAU2  a two-term creep function (s)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "emit/emit_header.h"
#include "fitting/cases.h"
#include "fitting/families/family.h"
#include "fitting/families/prony_family.h"
#include "fitting/histories.h"
#include "model/forms/prony.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define TICK_NS 1000000u /* 1 ms: a 1 kHz haptic loop */
#define N_TRAIN 12
#define N_HELDOUT 6
#define N_TICKS 5000 /* 5 s */
#define SEED 14u

static int parse_creep(const char *s, tf_creep *c, char *what, size_t n)
{
    double a, b, d, e;
    if (sscanf(s, "kelvin:%lf,%lf,%lf", &a, &b, &d) == 3) {
        *c = tf_creep_kelvin(a, b, d);
        snprintf(what, n, "[EFG-Kelvin]'s Kelvin solid k1 = %g MPa, k2 = %g MPa, eta = %g MPa s", a, b,
                 d);
        return 0;
    }
    if (sscanf(s, "two:%lf,%lf,%lf,%lf", &a, &b, &d, &e) == 4) {
        *c = (tf_creep){2, {b, e}, {a, d}};
        snprintf(what, n, "a two-term creep function");
        return 0;
    }
    return -1;
}

int main(int argc, char **argv)
{
    char what[256];
    tf_creep creep;
    if (argc != 5 || parse_creep(argv[2], &creep, what, sizeof what) != 0) {
        fprintf(stderr, "usage: creep_fit SCENE kelvin:K1,K2,ETA|two:W1,TAU1,W2,TAU2 OUT.h MAX_REL\n");
        return 2;
    }
    const double max_rel = strtod(argv[4], NULL);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *scene = tf_scene_load(&ctx, argv[1], NULL, 0);
    if (scene == NULL) {
        fprintf(stderr, "creep_fit: %s\n", ctx.err);
        return 1;
    }
    tf_fit_plan plan = scene->fit;
    tf_solver *solver = tf_solver_create(&scene->problem, NULL, &ctx);
    tf_cases cases;
    tf_histories hist;
    if (solver == NULL || tf_cases_build(&scene->problem, solver, &plan, &cases) != 0) {
        fprintf(stderr, "creep_fit: %s\n", ctx.err);
        return 1;
    }
    if (tf_histories_linear_creep(&ctx, &cases, &creep, TICK_NS, N_TRAIN, N_HELDOUT, N_TICKS, SEED,
                                  &hist) != 0) {
        fprintf(stderr, "creep_fit: %s\n", ctx.err);
        return 1;
    }
    cases.hist = &hist;
    printf("%s: %s\n", argv[1], what);
    for (int k = 0; k < creep.n; ++k) {
        printf("  creep term %d: weight %.4g, time constant %.4g s\n", k, creep.w[k], creep.tau[k]);
    }
    printf("  %d training and %d held-out histories of %d ticks of %u us, %u outputs\n", N_TRAIN,
           N_HELDOUT, N_TICKS, TICK_NS / 1000, cases.train.n_out);

    const tf_family *f = tf_family_find("prony");
    tf_family_result r;
    memset(&r, 0, sizeof r);
    r.family = f;
    if (f->select(&ctx, &cases, &plan, &r) != 0) {
        fprintf(stderr, "creep_fit: %s\n", ctx.err);
        return 1;
    }
    tf_model *m = r.model;
    double max, rms, rel;
    uint32_t n_hist;
    f->heldout(&ctx, m, &cases, &max, &rms, &rel, &n_hist);
    char orders[128];
    f->orders_text(m, TF_ORDERS_FULL, orders, sizeof orders);
    printf("  fitted: %s\n", orders);
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + 2 * k;
        printf("    term %u: weight %.4g, time constant %.4g s (realised by a = %a)\n", k,
               (double)pt[1] / tf_prony_hold_gain(pt[0]),
               tf_prony_realised_tau(tf_stateful_tick(m), pt[0]), (double)pt[0]);
    }
    double train_max, train_rms, peak;
    tf_stateful_history_errors(m, &hist.train, &train_max, &train_rms, &peak);
    printf("  training histories: max error %.3g mm, rms %.3g mm (peak %.3g mm)\n", train_max,
           train_rms, peak);
    printf("  held-out histories: max error %.3g mm, rms %.3g mm: %.3g %% of the peak "
           "displacement (bound %.3g %%)\n",
           max, rms, 100 * rel, 100 * max_rel);
    m->heldout_max = max;
    m->heldout_rms = rms;
    m->heldout_rel_max = rel;
    m->heldout_cases = n_hist;
    snprintf(m->name, sizeof m->name, "creep48");
    const tf_emit_info info = {.source = "block48 as a linear viscoelastic body, synthetic "
                                         "histories (tests/prony/creep_fit.c)",
                               .golden_seed = 14};
    tf_model *one[1] = {m};
    int rc = tf_emit_header(&ctx, argv[3], one, 1, &info);
    if (rc != 0) {
        fprintf(stderr, "creep_fit: %s\n", ctx.err);
    }
    const int ok = rc == 0 && rel <= max_rel;
    printf("%s: held-out error %.3g %% of the peak %s %.3g %%\n", ok ? "ok" : "FAIL", 100 * rel,
           rel <= max_rel ? "<=" : ">", 100 * max_rel);
    tf_model_free(m);
    tf_histories_free(&hist);
    tf_cases_free(&cases);
    tf_solver_destroy(solver);
    tf_scene_free(scene);
    return ok ? 0 : 1;
}
