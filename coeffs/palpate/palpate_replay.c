/*
 * palpate_replay.c — make demo-palpate's firmware loop and its replay
 * against true solves (palpate_replay.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "coeffs/palpate/palpate_replay.h"
#include "base/clock.h"
#include "fitting/region_sites.h"

/* the tool's monotonic clock (base/clock.h), in ns */
static double now_ns(void) { return 1e9 * tf_seconds(); }

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, size_t n)
{
    qsort(v, n, sizeof *v, cmp_double);
    return n ? v[n / 2] : 0;
}

void palpate_run_free(palpate_run *run)
{
    free(run->state);
    free(run->force);
    free(run->status);
    free(run->surface);
    free(run->surface_status);
    memset(run, 0, sizeof *run);
}

/* One tick of the servo: the firmware's calls on the caller's states. */
static int32_t tick(const palpate_models *m, const palpate_tick *t, float *st, float f[2][3])
{
    if (t->two) {
        float f2[6], tip2[6];
        memcpy(tip2, t->tip, sizeof tip2);
        int32_t s = tfit_region_pair(m->law, m->surf, st, tip2, f2);
        memcpy(f, f2, sizeof f2);
        return s;
    }
    f[1][0] = f[1][1] = f[1][2] = 0.0f;
    return tfit_region_force(m->law, st, t->tip[0], f[0]);
}

int palpate_loop(tf_ctx *ctx, const palpate_models *m, const palpate_tick *t, size_t n,
                 palpate_run *run)
{
    const size_t frames = n / PALPATE_DISPLAY_EVERY, w = 3 * m->n_out;
    memset(run, 0, sizeof *run);
    run->n = n;
    run->state = malloc((n + 1) * sizeof *run->state);
    run->force = malloc((n + 1) * sizeof *run->force);
    run->status = malloc((n + 1) * sizeof *run->status);
    run->surface = malloc((frames * w + 1) * sizeof *run->surface);
    run->surface_status = malloc((frames + 1) * sizeof *run->surface_status);
    double *ns = malloc((n + 1) * sizeof *ns), *fns = malloc((frames + 1) * sizeof *fns);
    if (!run->state || !run->force || !run->status || !run->surface || !run->surface_status ||
        !ns || !fns) {
        free(ns);
        free(fns);
        palpate_run_free(run);
        return tf_fail(ctx, "out of memory for %zu ticks", n);
    }
    float st[2 * TFIT_REGION_STATE_WORDS]; /* the caller's: instrument 1, then 2 */
    tfit_region_reset(m->law, st);
    tfit_region_reset(m->law, st + TFIT_REGION_STATE_WORDS);
    run->tick_ns_worst = 0;
    for (size_t k = 0; k < n; ++k) {
        double t0 = now_ns();
        run->status[k] = tick(m, &t[k], st, run->force[k]);
        ns[k] = now_ns() - t0;
        run->tick_ns_worst = fmax(run->tick_ns_worst, ns[k]);
        memcpy(run->state[k], st, sizeof st);
        if (k % PALPATE_DISPLAY_EVERY == PALPATE_DISPLAY_EVERY - 1 && k / PALPATE_DISPLAY_EVERY < frames) {
            size_t fr = k / PALPATE_DISPLAY_EVERY;
            float *u = run->surface + fr * w, f2[6];
            memcpy(f2, run->force[k], sizeof f2);
            t0 = now_ns();
            run->surface_status[fr] = t[k].two ? tfit_region_surface_pair(m->surf, st, f2, u)
                                               : tfit_region_surface(m->surf, st, f2, u);
            fns[fr] = now_ns() - t0;
        }
    }
    run->tick_ns = median(ns, n);
    run->frame_ns = median(fns, frames);
    free(ns);
    free(fns);
    return 0;
}

/* ---- the replay ------------------------------------------------------------ */

/* Solves A x = b for a k x k system (k <= 6) by Gaussian elimination with
 * partial pivoting; A and b are overwritten.  0, or -1 when singular. */
static int solve_small(int k, double *A, double *b)
{
    for (int c = 0; c < k; ++c) {
        int piv = c;
        for (int r = c + 1; r < k; ++r) {
            piv = fabs(A[r * k + c]) > fabs(A[piv * k + c]) ? r : piv;
        }
        if (!(fabs(A[piv * k + c]) > 0)) {
            return -1;
        }
        for (int j = 0; j < k; ++j) {
            double x = A[c * k + j];
            A[c * k + j] = A[piv * k + j];
            A[piv * k + j] = x;
        }
        double x = b[c];
        b[c] = b[piv];
        b[piv] = x;
        for (int r = c + 1; r < k; ++r) {
            double f = A[r * k + c] / A[c * k + c];
            for (int j = c; j < k; ++j) {
                A[r * k + j] -= f * A[c * k + j];
            }
            b[r] -= f * b[c];
        }
    }
    for (int c = k - 1; c >= 0; --c) {
        for (int j = c + 1; j < k; ++j) {
            b[c] -= A[c * k + j] * b[j];
        }
        b[c] /= A[c * k + c];
    }
    return 0;
}

/* Instrument i's proxy site (a, b) (mm) after a tick and the firmware's
 * contact displacement there, q - x(g) (chart frame, mm: the tip against
 * the rest surface at the proxy, §5.10 step 6). */
static void contact(const palpate_models *m, const float tip[3], const float *state,
                    double ab[2], double u[3])
{
    const double g[2] = {state[0], state[1]}, p[3] = {tip[0], tip[1], tip[2]};
    double x[3], q[3];
    palpate_rest_point(m->law_host, g, x);
    palpate_to_chart(&m->grid, p, q);
    ab[0] = x[0];
    ab[1] = x[1];
    for (int i = 0; i < 3; ++i) {
        u[i] = q[i] - x[i];
    }
}

/* The chart-frame force of a scene-frame one. */
static void to_chart_force(const palpate_grid *g, const float F[3], double Fc[3])
{
    for (int i = 0; i < 3; ++i) {
        Fc[i] = g->rot[3 * i] * F[0] + g->rot[3 * i + 1] * F[1] + g->rot[3 * i + 2] * F[2];
    }
}

/* A sampled tick: its index, and its sites' indices in the solved sets. */
typedef struct sample {
    size_t k, s1, s2;
} sample;

static int in_contact(const float *state)
{
    return state[2] == 1.0f;
}

/* The ticks replayed: every `every`-th display tick with instrument 1 in
 * contact (with instrument 2 too when both are in the scene). */
static size_t choose(const palpate_run *run, const palpate_tick *t, size_t every, sample *s)
{
    size_t n = 0, frame = 0;
    for (size_t k = PALPATE_DISPLAY_EVERY - 1; k < run->n; k += PALPATE_DISPLAY_EVERY, ++frame) {
        if (frame % every != 0 || !in_contact(run->state[k][0]) ||
            (t[k].two && !in_contact(run->state[k][1]))) {
            continue;
        }
        s[n++].k = k;
    }
    return n;
}

/* The largest |model - truth| over the outputs, mm: the firmware's
 * surface u (scene frame) against sum_i U_i Fc_i (U: 3 n_out x 3
 * column-major per site, per unit chart-axis force). */
static double surface_error(const float *u, size_t n_out, const double *const U[2],
                            const double Fc[2][3], int two)
{
    double worst = 0;
    const size_t rows = 3 * n_out;
    for (size_t j = 0; j < n_out; ++j) {
        double d2 = 0;
        for (int i = 0; i < 3; ++i) {
            size_t r = 3 * j + (size_t)i;
            double truth = 0;
            for (int s = 0; s < 1 + two; ++s) {
                for (int c = 0; c < 3; ++c) {
                    truth += U[s][(size_t)c * rows + r] * Fc[s][c];
                }
            }
            d2 += (u[r] - truth) * (u[r] - truth);
        }
        worst = fmax(worst, sqrt(d2));
    }
    return worst;
}

/* The cross compliance C(i, j) of sites i of a and j of b (recorded while
 * b was solved with a as partners), or NULL. */
static const double *cross(const tf_region_sites *b, size_t na, size_t i, size_t j)
{
    for (size_t k = 0; k < b->n_pairs; ++k) {
        if (b->pair[2 * k] == i && b->pair[2 * k + 1] == na + j) {
            return b->cross + 9 * k;
        }
    }
    return NULL;
}

/* The true forces at the firmware's contact displacements: C F = u with
 * C the sites' compliance (6 x 6 with the cross terms for two). */
static int true_forces(const double *C1, const double *C2, const double *C12, int two,
                       const double u[2][3], double F[2][3])
{
    const int k = two ? 6 : 3;
    double A[36], b[6];
    for (int r = 0; r < k; ++r) {
        b[r] = u[r / 3][r % 3];
        for (int c = 0; c < k; ++c) {
            int i = r % 3, j = c % 3;
            A[r * k + c] = r < 3 && c < 3   ? C1[3 * i + j]
                           : r >= 3 && c >= 3 ? C2[3 * i + j]
                           : r < 3            ? C12[3 * i + j]  /* at 1 under a force at 2 */
                                              : C12[3 * j + i]; /* reciprocity: C21 = C12^T */
        }
    }
    if (solve_small(k, A, b) != 0) {
        return -1;
    }
    for (int r = 0; r < k; ++r) {
        F[r / 3][r % 3] = b[r];
    }
    return 0;
}

/* The errors of one sampled tick into e. */
static int judge(const palpate_models *m, const palpate_tick *t, const palpate_run *run,
                 const sample *s, const tf_region_sites *a, const tf_region_sites *b,
                 palpate_errors *e)
{
    const size_t k = s->k, frame = k / PALPATE_DISPLAY_EVERY;
    const int two = t[k].two;
    double ab[2], u[2][3], Fc[2][3], Ft[2][3];
    for (int i = 0; i < 1 + two; ++i) {
        contact(m, t[k].tip[i], run->state[k][i], ab, u[i]);
        to_chart_force(&m->grid, run->force[k][i], Fc[i]);
    }
    const double *C12 = two ? cross(b, a->n, s->s1, s->s2) : NULL;
    if (two && C12 == NULL) {
        return -1;
    }
    const double *U[2] = {a->U + 9 * a->n_out * s->s1, two ? b->U + 9 * b->n_out * s->s2 : NULL};
    double ds = surface_error(run->surface + frame * 3 * m->n_out, m->n_out, U, Fc, two);
    e->surface = fmax(e->surface, 100 * ds / m->peak);
    if (run->status[k] != TFIT_OK) { /* the envelope's force, by design: no truth to match */
        e->skipped++;
        return 0;
    }
    if (true_forces(a->C + 9 * s->s1, two ? b->C + 9 * s->s2 : NULL, C12, two, u, Ft) != 0) {
        return -1;
    }
    for (int i = 0; i < 1 + two; ++i) {
        double d[3] = {Fc[i][0] - Ft[i][0], Fc[i][1] - Ft[i][1], Fc[i][2] - Ft[i][2]};
        e->force = fmax(e->force, 100 * sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / m->R_F);
    }
    return 0;
}

int palpate_replay(tf_ctx *ctx, tf_solver *sv, const tf_problem *p, const tf_contact_region *r,
                   const palpate_models *m, const palpate_tick *t, const palpate_run *run,
                   size_t every, palpate_errors *e)
{
    double t0 = now_ns();
    memset(e, 0, sizeof *e);
    sample *smp = malloc((run->n / PALPATE_DISPLAY_EVERY + 1) * sizeof *smp);
    double *ab1 = malloc((run->n / PALPATE_DISPLAY_EVERY + 1) * 2 * sizeof *ab1);
    double *ab2 = malloc((run->n / PALPATE_DISPLAY_EVERY + 1) * 2 * sizeof *ab2);
    if (!smp || !ab1 || !ab2) {
        free(smp);
        free(ab1);
        free(ab2);
        return tf_fail(ctx, "out of memory");
    }
    size_t n = choose(run, t, every, smp), n1 = 0, n2 = 0;
    for (size_t i = 0; i < n; ++i) { /* the proxies' sites */
        double u[3];
        const size_t k = smp[i].k;
        smp[i].s1 = n1;
        contact(m, t[k].tip[0], run->state[k][0], ab1 + 2 * n1++, u);
        if (t[k].two) {
            smp[i].s2 = n2;
            contact(m, t[k].tip[1], run->state[k][1], ab2 + 2 * n2++, u);
        }
    }
    tf_region_sites a = {0}, b = {0};
    int rc = tf_region_sites_solve(ctx, sv, p, r, ab1, n1, NULL, 0, &a);
    if (rc == 0 && n2 > 0) { /* cross compliances with every site of a, as b is solved */
        rc = tf_region_sites_solve(ctx, sv, p, r, ab2, n2, &a, INFINITY, &b);
    }
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        rc = judge(m, t, run, &smp[i], &a, &b, e);
        if (rc != 0) {
            rc = tf_fail(ctx, "tick %zu: no cross compliance of its two sites, or a singular "
                              "compliance", smp[i].k);
        }
        e->pair_ticks += (size_t)t[smp[i].k].two;
    }
    e->ticks = n;
    e->sites = n1 + n2;
    e->seconds = (now_ns() - t0) * 1e-9;
    if (n2 > 0) {
        tf_region_sites_free(&b);
    }
    if (n1 > 0) {
        tf_region_sites_free(&a);
    }
    free(smp);
    free(ab1);
    free(ab2);
    return rc;
}
