/*
 * tfit_zhou2017.c — the seed-000 model structure (Zhou et al. 2017, §3).
 *
 * For each force axis a (x, y, z):
 *   contact displacement  d_a = r_a(g_a), a polynomial of order lambda_a in
 *                         the normalised force component alone (eqs 40-42);
 *   normalised            t_a = d_a * s_a, s_a = 1 / sum |r_a|, so |t_a| <= 1;
 *   for each displacement component c, the surface coefficients
 *                         p_i = beta_{a,c,i}(t_a), polynomials of order k (eq 46),
 *   and at every output node j with normalised rest coordinates (X_j, Y_j)
 *   the separable surface (eq 44)
 *     S = (p_0 + p_1 T_1(X) + ... + p_A T_A(X)) + (p_{A+1} T_1(Y) + ... + p_{A+B} T_B(Y)).
 * The displacement is the superposition over force axes:
 *     out[3j + c] = (S_x + S_y) + S_z.
 *
 * coef = input map (12)
 *      | for a in x,y,z: r_a[0..lambda_a] (ascending), s_a
 *      | for a in x,y,z, c in x,y,z: beta[A+B+1][k+1] (row i = p_i, ascending in t)
 *      | XY[n_out][2]
 * dims = lambda[3], then (A, B, k) for (a, c) in row-major order.
 * Every polynomial is a Chebyshev series (API version 3), evaluated by
 * Clenshaw's recurrence (tfit_cheb, docs/header-format.md §5.4); the Y part
 * has no constant term (tfit_cheb_tail).
 */
#include "tfit_internal.h"

/* Adds (or, for the first axis, stores) one surface S_{a,c} at every node. */
static void add_surface(const float *p, uint32_t ax, uint32_t by, const float *xy, uint32_t n_out,
                        float *out, int first)
{
    for (uint32_t j = 0u; j < n_out; ++j) {
        float s = tfit_cheb(p, ax, xy[2u * j]);
        if (by > 0u) {
            s = s + tfit_cheb_tail(p + ax, by, xy[2u * j + 1u]);
        }
        out[3u * j] = first ? s : out[3u * j] + s;
    }
}

void tfit_eval_zhou2017(const tfit_model *m, const float g[3], float *out)
{
    const uint32_t *dm = m->dims;
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *xy = m->coef + (m->n_coef - 2u * m->n_out);
    float t[3];
    float p[TFIT_ZHOU_MAX_ROWS];

    for (uint32_t a = 0u; a < 3u; ++a) {
        float d = tfit_cheb(c, dm[a], g[a]);
        c += dm[a] + 1u;
        t[a] = d * c[0];
        c += 1;
    }
    for (uint32_t a = 0u; a < 3u; ++a) {
        for (uint32_t comp = 0u; comp < 3u; ++comp) {
            const uint32_t *o = dm + 3u + 3u * (3u * a + comp);
            const uint32_t rows = o[0] + o[1] + 1u;
            for (uint32_t i = 0u; i < rows; ++i) {
                p[i] = tfit_cheb(c + i * (o[2] + 1u), o[2], t[a]);
            }
            c += rows * (o[2] + 1u);
            add_surface(p, o[0], o[1], xy, m->n_out, out + comp, a == 0u);
        }
    }
}
