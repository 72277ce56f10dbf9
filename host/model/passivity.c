/*
 * passivity.c — see passivity.h.
 */
#include "model/passivity.h"

#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "model/basis.h"

/* Terms of the largest basis the target accepts. */
#define MAX_TERMS ((TFIT_MAX_DEGREE + 1) * (TFIT_MAX_DEGREE + 2) * (TFIT_MAX_DEGREE + 3) / 6)
#define GRID_STEP 0.1       /* normalised units: 4,169 points inside the ball */
#define SPHERE_POINTS 1000u /* on |g| = 1, where a polynomial bends most */

/* J = dP/dg W at normalised input g (N/mm): the contact tables hold, per force
 * component i, t coefficients after the input map (header-format.md §3). */
static void jacobian(const tf_model *m, const double g[3], double j[9])
{
    const uint32_t p = m->dims[0], t = tf_terms(p);
    const float *w = m->coef + 3, *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    double phi[MAX_TERMS], dphi[MAX_TERMS][3], dp[9] = {0};
    tf_basis_grad(p, g, phi, dphi);
    for (int i = 0; i < 3; ++i) {
        for (uint32_t q = 0; q < t; ++q) {
            for (int v = 0; v < 3; ++v) {
                dp[3 * i + v] += (double)c[(uint32_t)i * t + q] * dphi[q][v];
            }
        }
    }
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            j[3 * i + k] = dp[3 * i] * (double)w[k] + dp[3 * i + 1] * (double)w[3 + k] +
                           dp[3 * i + 2] * (double)w[6 + k];
        }
    }
}

/* Eigenvalues (ascending) of the symmetric 3x3 matrix s (LAPACK dsyev). */
static int sym_eigs(double s[9], double e[3])
{
    return LAPACKE_dsyev(LAPACK_ROW_MAJOR, 'N', 'U', 3, s, 3, e) == 0 ? 0 : -1;
}

/* Folds one sample into out. */
static int sample(const tf_model *m, const double g[3], tf_passivity *out)
{
    double j[9], s[9], jtj[9], e[3], n[3];
    jacobian(m, g, j);
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
            s[3 * a + b] = 0.5 * (j[3 * a + b] + j[3 * b + a]);
            jtj[3 * a + b] = j[a] * j[b] + j[3 + a] * j[3 + b] + j[6 + a] * j[6 + b];
        }
    }
    if (sym_eigs(s, e) != 0 || sym_eigs(jtj, n) != 0) {
        return -1;
    }
    if (out->samples == 0 || e[0] < out->min_eig) {
        out->min_eig = e[0];
        memcpy(out->worst_g, g, sizeof out->worst_g);
    }
    out->max_stiffness = fmax(out->max_stiffness, sqrt(fmax(n[2], 0)));
    out->samples++;
    return 0;
}

/* delta = x0 + W^-1 g, for the message. */
static void to_delta(const tf_model *m, const double g[3], double delta[3])
{
    double w[9], b[3] = {g[0], g[1], g[2]};
    lapack_int piv[3];
    for (int i = 0; i < 9; ++i) {
        w[i] = (double)m->coef[3 + i];
    }
    if (LAPACKE_dgesv(LAPACK_ROW_MAJOR, 3, 1, w, 3, piv, b, 1) != 0) {
        b[0] = b[1] = b[2] = NAN;
    }
    for (int a = 0; a < 3; ++a) {
        delta[a] = (double)m->coef[a] + b[a];
    }
}

int tf_passivity_measure(tf_ctx *ctx, const tf_model *m, tf_passivity *out)
{
    memset(out, 0, sizeof *out);
    if (m->family != TFIT_FAMILY_CONTACT) {
        return tf_fail(ctx, "passivity: %s is not a contact model", m->name);
    }
    const int n = (int)lround(1 / GRID_STEP);
    int rc = 0;
    for (int x = -n; x <= n && rc == 0; ++x) {
        for (int y = -n; y <= n && rc == 0; ++y) {
            for (int z = -n; z <= n && rc == 0; ++z) {
                const double g[3] = {x * GRID_STEP, y * GRID_STEP, z * GRID_STEP};
                if (g[0] * g[0] + g[1] * g[1] + g[2] * g[2] <= 1 + 1e-12) {
                    rc = sample(m, g, out);
                }
            }
        }
    }
    /* Fibonacci points on the unit sphere: even cover without a grid's poles. */
    const double golden = M_PI * (3 - sqrt(5));
    for (uint32_t k = 0; k < SPHERE_POINTS && rc == 0; ++k) {
        const double z = 1 - (2 * k + 1) / (double)SPHERE_POINTS, r = sqrt(1 - z * z);
        const double g[3] = {r * cos(golden * k), r * sin(golden * k), z};
        rc = sample(m, g, out);
    }
    if (rc != 0) {
        return tf_fail(ctx, "passivity: LAPACK failed on the stiffness of %s", m->name);
    }
    to_delta(m, out->worst_g, out->worst_delta);
    return 0;
}

int tf_passivity_require(tf_ctx *ctx, tf_model *m)
{
    tf_passivity p;
    if (tf_passivity_measure(ctx, m, &p) != 0) {
        return -1;
    }
    m->stiffness_min = p.min_eig;
    m->stiffness_max = p.max_stiffness;
    m->passivity_samples = p.samples;
    if (!(p.min_eig > 0)) {
        tf_fail(ctx,
                "contact model %s is not passive: the symmetric part of its stiffness has "
                "eigenvalue %.4g N/mm at contact displacement (%.4g, %.4g, %.4g) mm (one of %u "
                "samples of the envelope), so the haptic loop would create energy there; "
                "refusing to emit it (fit a lower degree or a smaller force envelope)",
                m->name, p.min_eig, p.worst_delta[0], p.worst_delta[1], p.worst_delta[2],
                p.samples);
        return 1;
    }
    return 0;
}
