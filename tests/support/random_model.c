/*
 * random_model.c — see random_model.h.
 */
#include "random_model.h"

#include <math.h>
#include <string.h>
#include <stdio.h>

#include "fitting/families/zhou2017.h"
#include "model/forms/prony.h"
#include "model/forms/resonant.h"
#include "random_region.h"

static uint32_t pick(tf_rng *r, uint32_t lo, uint32_t hi)
{
    return lo + tf_rng_below(r, hi - lo + 1);
}

static uint32_t random_n_out(tf_rng *r, int small)
{
    uint32_t u = tf_rng_below(r, 100);
    if (small || u < 70) {
        return pick(r, 1, 8);
    }
    return u < 95 ? pick(r, 9, 64) : pick(r, 65, 400);
}

/* A coefficient: random sign and mantissa, exponent in [elo, ehi]. */
static float random_coef(tf_rng *r, int elo, int ehi)
{
    if (tf_rng_below(r, 20) == 0) {
        return 0.0f;
    }
    double m = tf_rng_range(r, 1.0, 2.0);
    int e = elo + (int)tf_rng_below(r, (uint32_t)(ehi - elo + 1));
    return (float)(ldexp(m, e) * (tf_rng_below(r, 2) ? -1.0 : 1.0));
}

static void random_map(tf_rng *r, tf_model *m)
{
    double scale = pow(10.0, tf_rng_range(r, -3.0, 3.0));
    double x0[3] = {0, 0, 0};
    uint32_t kind = tf_rng_below(r, 10);
    if (kind < 4) {
        tf_model_set_ball(m, x0, scale);
        return;
    }
    for (int i = 0; i < 3; ++i) {
        x0[i] = tf_rng_range(r, -2.0, 2.0) * scale;
    }
    if (kind < 7) {
        tf_model_set_ball(m, x0, scale);
        return;
    }
    double w[9];
    for (int i = 0; i < 9; ++i) {
        w[i] = (i % 4 == 0 ? 1.0 : 0.0) + tf_rng_range(r, -0.45, 0.45);
        w[i] /= scale * pow(10.0, tf_rng_range(r, -1.0, 1.0));
    }
    tf_model_set_map(m, x0, w);
}

static void random_dims(tf_rng *r, tfit_family f, uint32_t *dims, uint32_t *n_dims, int small)
{
    uint32_t pmax = small ? 4 : TFIT_MAX_DEGREE;
    switch (f) {
    case TFIT_FAMILY_MODAL:
        dims[0] = pick(r, 0, pmax);
        dims[1] = tf_rng_below(r, 10) == 0 ? TFIT_MAX_RANK : pick(r, 1, small ? 4 : 16);
        *n_dims = 2;
        break;
    case TFIT_FAMILY_MODAL_Q15: /* {p >= 1, 8} */
        dims[0] = pick(r, 1, pmax);
        dims[1] = TFIT_MODAL_Q15_RANK;
        *n_dims = TFIT_MODAL_Q15_DIMS;
        break;
    case TFIT_FAMILY_ZHOU2017:
        for (int a = 0; a < 3; ++a) {
            dims[a] = pick(r, 0, small ? 3 : TFIT_MAX_DEGREE);
        }
        for (int i = 3; i < TFIT_ZHOU2017_DIMS; ++i) {
            dims[i] = pick(r, 0, small ? 3 : ((i % 3) == 2 ? TFIT_MAX_DEGREE : TFIT_ZHOU_MAX_ORDER));
        }
        *n_dims = TFIT_ZHOU2017_DIMS;
        break;
    case TFIT_FAMILY_PRONY: /* {p, r (0: nodal), K, tick_ns} */
        dims[0] = pick(r, 0, pmax);
        dims[1] = tf_rng_below(r, 2) ? 0 : pick(r, 1, small ? 4 : 16);
        dims[2] = pick(r, 0, small ? 3 : TFIT_PRONY_MAX_TERMS);
        dims[3] = (uint32_t)pow(10.0, tf_rng_range(r, 3.0, 8.0)); /* 1 us .. 0.1 s */
        *n_dims = TFIT_PRONY_DIMS;
        break;
    case TFIT_FAMILY_CUT: /* {p, K intervals in s} */
        dims[0] = pick(r, 0, pmax);
        dims[1] = pick(r, 1, small ? 4 : 16);
        *n_dims = TFIT_CUT_DIMS;
        break;
    case TFIT_FAMILY_RESONANT: /* {p, r (0: nodal), K, tick_ns} */
        dims[0] = pick(r, 0, pmax);
        dims[1] = tf_rng_below(r, 2) ? 0 : pick(r, 1, small ? 4 : 16);
        dims[2] = pick(r, 0, small ? 3 : TFIT_RESONANT_MAX_MODES);
        dims[3] = (uint32_t)pow(10.0, tf_rng_range(r, 3.0, 8.0)); /* 1 us .. 0.1 s */
        *n_dims = TFIT_RESONANT_DIMS;
        break;
    default:
        dims[0] = pick(r, 0, pmax);
        *n_dims = 1;
        break;
    }
}

/* Prony terms: decays exp(-T/tau) with T/tau log-uniform in [1e-5, 20], now
 * and then exactly 0 or the largest emittable decay; gains either those of
 * a physical creep function (weights >= 0 summing to at most 1) or random
 * over many binades, so that the clamp of h acts too. */
static void prony_terms(tf_rng *r, tf_model *m, int physical)
{
    float *pt = tf_model_tables(m);
    double left = 1.0;
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        uint32_t kind = tf_rng_below(r, 16);
        double ratio = pow(10.0, tf_rng_range(r, -5.0, log10(20.0)));
        pt[2 * k] = kind == 0 ? 0.0f : (kind == 1 ? 1.0f - 0x1p-19f : (float)exp(-ratio));
        if (physical) {
            double w = left * tf_rng_uniform(r);
            left -= w;
            pt[2 * k + 1] = (float)(w * tf_prony_hold_gain(pt[2 * k]));
        } else {
            pt[2 * k + 1] = random_coef(r, -20, 6);
        }
    }
}

/* Resonant modes: omega T log-uniform in [1e-2, 1.5] and zeta in
 * [1e-3, 2], redrawn until the float recursion carries them
 * (tf_resonant_params_check: contraction, resolution); weights either
 * physical-looking (in [-1, 1]) or random over many binades, so that the
 * clamp of h acts too. */
static void resonant_modes(tf_rng *r, tf_model *m, int physical)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const double tick = tf_stateful_tick(m);
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        double omega, zeta;
        do {
            omega = pow(10.0, tf_rng_range(r, -2.0, log10(1.5))) / tick;
            zeta = pow(10.0, tf_rng_range(r, -3.0, log10(2.0)));
        } while (tf_resonant_params_check(&ctx, omega, zeta, tick) != 0);
        double w[3];
        for (int i = 0; i < 3; ++i) {
            w[i] = physical ? tf_rng_range(r, -1, 1) : (double)random_coef(r, -20, 6);
        }
        tf_resonant_set_mode(m, k, omega, zeta, w);
    }
}

/* The words after a modal_q15 model's amplitudes: scales v_k over many
 * binades (so that some a_k v_k saturate), S, and row words whose halves
 * are random within +-16255, a tenth of them at the extremes. */
static uint32_t q15_half(tf_rng *r)
{
    uint32_t k = tf_rng_below(r, 20);
    int32_t q = k == 0 ? 16255 : k == 1 ? -16255 : (int32_t)tf_rng_below(r, 32511) - 16255;
    return (uint32_t)q;
}

static void q15_tables(tf_rng *r, tf_model *m)
{
    float *v = tf_model_tables(m) + TFIT_MODAL_Q15_RANK * tf_terms(m->dims[0]);
    for (uint32_t k = 0; k < TFIT_MODAL_Q15_RANK; ++k) {
        v[k] = (float)pow(10.0, tf_rng_range(r, -3.0, 6.0)) * (tf_rng_below(r, 2) ? 1.0f : -1.0f);
    }
    v[TFIT_MODAL_Q15_RANK] = (float)pow(10.0, tf_rng_range(r, -12.0, 3.0));
    float *rows = v + TFIT_MODAL_Q15_RANK + 1;
    for (uint32_t i = 0; i < 3 * m->n_out * TFIT_MODAL_Q15_WORDS; ++i) {
        const uint32_t w = (q15_half(r) & 0xffffu) | ((q15_half(r) + 16384u) << 16);
        memcpy(&rows[i], &w, sizeof w);
    }
}

static void fill_tables(tf_rng *r, tf_model *m)
{
    /* binade spread: well scaled, moderately, or wildly ill-scaled */
    uint32_t spread = tf_rng_below(r, 3);
    int elo = spread == 0 ? -4 : (spread == 1 ? -40 : -149);
    int ehi = spread == 0 ? 4 : (spread == 1 ? 30 : 90);
    float *c = tf_model_tables(m);
    uint32_t n = m->n_coef - TFIT_INPUT_MAP_FLOATS;
    uint32_t n_xy = m->family == TFIT_FAMILY_ZHOU2017 ? 2 * m->n_out : 0;
    for (uint32_t i = 0; i < n - n_xy; ++i) {
        c[i] = random_coef(r, elo, ehi);
    }
    if (m->family == TFIT_FAMILY_PRONY) {
        prony_terms(r, m, spread == 0);
    } else if (m->family == TFIT_FAMILY_RESONANT) {
        resonant_modes(r, m, spread == 0);
    } else if (m->family == TFIT_FAMILY_MODAL_Q15) {
        q15_tables(r, m);
    }
    for (uint32_t i = n - n_xy; i < n; ++i) {
        uint32_t k = tf_rng_below(r, 12);
        c[i] = k == 0 ? 1.0f : (k == 1 ? -1.0f : (k == 2 ? 0.0f : (float)tf_rng_range(r, -1, 1)));
    }
    for (uint32_t j = 0; j < m->n_out; ++j) {
        m->node_ids[j] = (uint32_t)(tf_rng_next(r) >> 40);
    }
}

/* zhou2017: the scales s_a by the fitter's rule (tf_zhou_scale), so t_a
 * stays in [-1, 1] as in every fitted model; a random s_a would put the
 * Chebyshev series in t outside the interval they are made for. */
static void zhou_scales(tf_model *m)
{
    float *c = tf_model_tables(m);
    for (int a = 0; a < 3; ++a) {
        const uint32_t lambda = m->dims[a];
        c[lambda + 1] = tf_zhou_scale(c, lambda);
        c += lambda + 2;
    }
}

/* Halve every non-coordinate table entry until the model validates (the
 * zhou2017 scales are kept by the rule: halving a law doubles its scale). */
static int make_emittable(tf_model *m)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    float *c = tf_model_tables(m);
    uint32_t n = m->n_coef - TFIT_INPUT_MAP_FLOATS;
    uint32_t n_xy = m->family == TFIT_FAMILY_ZHOU2017 ? 2 * m->n_out : 0;
    /* a prony model's decays stay as drawn (halving its gains is harmless) */
    uint32_t n_decays = m->family == TFIT_FAMILY_PRONY ? m->dims[2] : 0;
    /* a resonant model's transition matrices too (its weights may halve) */
    uint32_t n_modes = m->family == TFIT_FAMILY_RESONANT ? m->dims[2] : 0;
    /* a modal_q15 model's scales and row words stay as drawn (valid) */
    if (m->family == TFIT_FAMILY_MODAL_Q15) {
        n_xy = TFIT_MODAL_Q15_RANK + 1 + 3 * m->n_out * TFIT_MODAL_Q15_WORDS;
    }
    for (int tries = 0; tries < 400; ++tries) {
        if (tf_model_validate(&ctx, m) == 0) {
            return 0;
        }
        for (uint32_t i = 0; i < n - n_xy; ++i) {
            if (!(i < 2 * n_decays && i % 2 == 0) && !(i < 7 * n_modes && i % 7 < 4)) {
                c[i] = ldexpf(c[i], -2);
            }
        }
        if (m->family == TFIT_FAMILY_ZHOU2017) {
            zhou_scales(m);
        }
    }
    return -1;
}

/* A region law or surface (random_region.c: a random chart, grid and
 * stiffness field; a surface of random rank, degree, site modes and
 * outputs), built and checked by model/region_model.c. */
static tf_model *random_region_model(tf_rng *r, const char *name, tfit_family family, int small)
{
    tf_ctx ctx;
    tf_random_region g;
    tf_ctx_init(&ctx);
    tf_random_region_draw(r, small ? 5 : 16, &g);
    tf_model *m = family == TFIT_FAMILY_REGION
                      ? tf_random_region_law(&ctx, &g, name)
                      : tf_random_region_surface(&ctx, r, &g, name, pick(r, 1, small ? 4 : 16),
                                                 pick(r, 1, TFIT_REGION_SURFACE_MAX_DEGREE),
                                                 (int)tf_rng_below(r, 2), random_n_out(r, small));
    if (m == NULL) {
        fprintf(stderr, "random region model: %s\n", ctx.err);
    }
    return m;
}

tf_model *tf_random_model(tf_rng *r, const char *name, tfit_family family, int small)
{
    if (family == TFIT_FAMILY_REGION || family == TFIT_FAMILY_REGION_SURFACE) {
        return random_region_model(r, name, family, small);
    }
    /* family 0: the stateless families (their sequences predate prony,
     * which is drawn only when asked for) */
    static const tfit_family families[] = {TFIT_FAMILY_NODAL, TFIT_FAMILY_NODAL,
                                           TFIT_FAMILY_MODAL, TFIT_FAMILY_ZHOU2017,
                                           TFIT_FAMILY_CONTACT};
    tfit_family f = family ? family : families[tf_rng_below(r, 5)];
    uint32_t dims[TFIT_ZHOU2017_DIMS], n_dims;
    random_dims(r, f, dims, &n_dims, small);
    uint32_t n_out = f == TFIT_FAMILY_CONTACT ? 1 : random_n_out(r, small);
    return tf_random_model_of(r, name, f, dims, n_dims, n_out);
}

tf_model *tf_random_model_of(tf_rng *r, const char *name, tfit_family f, const uint32_t *dims,
                             uint32_t n_dims, uint32_t n_out)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, name, f, n_out, dims, n_dims);
    if (m == NULL) {
        fprintf(stderr, "random model: %s\n", ctx.err);
        return NULL;
    }
    random_map(r, m);
    fill_tables(r, m);
    if (f == TFIT_FAMILY_ZHOU2017) {
        zhou_scales(m);
    }
    if (make_emittable(m) != 0) {
        fprintf(stderr, "random model %s: cannot scale into range\n", name);
        tf_model_free(m);
        return NULL;
    }
    return m;
}

int32_t tf_random_q31_word(tf_rng *r)
{
    switch (tf_rng_below(r, 6)) {
    case 0:
        return (int32_t)(uint32_t)tf_rng_next(r); /* anywhere */
    case 1:
        return (int32_t)(tf_rng_next(r) >> 40) - (1 << 23); /* near zero */
    case 2:
        return tf_rng_below(r, 2) ? INT32_MAX - (int32_t)tf_rng_below(r, 4)
                                  : INT32_MIN + (int32_t)tf_rng_below(r, 4);
    default:
        return (int32_t)((uint32_t)tf_rng_next(r) >> 2) - (1 << 29); /* |x| < 2^29 */
    }
}
