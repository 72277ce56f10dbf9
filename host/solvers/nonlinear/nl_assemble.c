/*
 * nl_assemble.c — internal forces and consistent tangent of the total
 * Lagrangian Galerkin system (nl_internal.h).
 *
 * At a Gauss point with gradients G_i = grad_X phi_i and the deformation
 * gradient F = I + sum_i d_i (x) G_i, the law gives the second Piola-
 * Kirchhoff stress S and C = dS/dE (materials/material.h).  With
 * P = F S the internal force of DOF (i, a) is sum_g w_g (P G_i)_a, and the
 * tangent is the material part B^T C B, B the Voigt rows of
 * dE = sym(F^T dF) (B_NL), plus the geometric part delta_ab G_i . S G_j
 * (e.g. Belytschko, Liu & Moran, Nonlinear Finite Elements, 2nd ed., §4.9
 * and §6.4).  Laws with small-strain kinematics (linear, seed 001's Kelvin)
 * take F = I in B and no geometric part: S is then the stress of linear
 * theory and B seed 001's eq 22.
 *
 * Volumetric locking (nu = 0.49): the linear solver's B-bar replaces
 * lambda (div u)^2 / 2 by lambda (cell average of div u)^2 / 2.  Its finite
 * strain form here (ours): the energy gains, per cell,
 *     V U(Jbar) - sum_g w_g U(J_g),  U(J) = lambda_v (J - 1)^2 / 2,
 *     Jbar = sum_g w_g J_g / V  (the cell's deformed volume ratio),
 * which linearises to exactly the linear B-bar (so the small-load limit is
 * the linear solver's answer) and vanishes for a homogeneous deformation.
 * A law whose volumetric energy is quadratic in tr E instead (its volume
 * measure TF_VOLUME_GREEN_TRACE: St. Venant-Kirchhoff, lambda (tr E)^2 / 2)
 * takes U of tr E: subtracting U(J) from its energy left a point energy
 * that is not convex at a few per cent of strain (block48's tangent lost
 * definiteness at 0.3 N tangential); with tr E the remainder is mu E:E.
 * Its force is sum_g w_g q_g dJ_g with q_g = U'(Jbar) - U'(J_g); for a
 * time-dependent law (TF_MATERIAL_HISTORY: the Kelvin laws) q relaxes with
 * the law's g(t) (a per-point history), and for small-strain laws
 * J = 1 + div u.
 */
#include <cblas.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "materials/kinematics.h"
#include "solvers/assemble.h"
#include "solvers/nonlinear/nl_internal.h"

/* Cells computed in parallel before they are added in cell order (the
 * same sums whatever the thread count): all of them for the forces, and
 * for the tangent as many as 64 MB of cell matrices hold.  Few large
 * batches: every batch ends in a barrier, and on a loaded machine threads
 * spinning there took 90 % of a small solve's time with batches of 32. */
#define TANGENT_BATCH_BYTES (64.0 * 1024 * 1024)

/* One thread's buffers for one cell. */
typedef struct cell_buf {
    double *dl, *bs, *cbs, *gs, *sgs, *hs, *hc, *dj, *hv, *sv, *ms, *o;
    double *pt;   /* per point: F(9) S(6) C(36) J, q~, kappa, P(9), c(6), lambda_v, material */
} cell_buf;

#define PT_STRIDE 72
/* per point: F, S (Voigt), C, J - 1, q~, kappa, P, c (Voigt: d theta = j c . dE), its
 * material's lambda_v and the material's index (nl_internal.h: mats) */
enum {
    PT_F = 0, PT_S = 9, PT_C = 15, PT_J = 51, PT_Q = 52, PT_KAPPA = 53, PT_P = 54, PT_CV = 63,
    PT_LAMBDA = 69, PT_MAT = 70
};

static int buf_init(cell_buf *b, size_t np, size_t m)
{
    size_t m3 = 3 * m;
    memset(b, 0, sizeof *b);
    b->dl = malloc(m3 * sizeof *b->dl);
    b->bs = malloc(6 * np * m3 * sizeof *b->bs);
    b->cbs = malloc(6 * np * m3 * sizeof *b->cbs);
    b->gs = malloc(3 * np * m * sizeof *b->gs);
    b->sgs = malloc(3 * np * m * sizeof *b->sgs);
    b->hs = malloc(np * m3 * sizeof *b->hs);
    b->hc = malloc(np * m3 * sizeof *b->hc);
    b->dj = malloc(np * m3 * sizeof *b->dj);
    b->hv = malloc(np * m3 * sizeof *b->hv);
    b->sv = malloc(m3 * sizeof *b->sv);
    b->ms = malloc(m * m * sizeof *b->ms);
    b->o = malloc(9 * m * m * sizeof *b->o);
    b->pt = malloc(np * PT_STRIDE * sizeof *b->pt);
    return b->dl && b->bs && b->cbs && b->gs && b->sgs && b->hs && b->hc && b->dj &&
                   b->hv && b->sv && b->ms && b->o && b->pt
               ? 0
               : -1;
}

static void buf_free(cell_buf *b)
{
    void *p[] = {b->dl, b->bs, b->cbs, b->gs, b->sgs, b->hs, b->hc, b->dj, b->hv, b->sv,
                 b->ms, b->o, b->pt};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; ++k) {
        free(p[k]);
    }
}

static void tensor_of_voigt(const double v[6], double t[9])
{
    for (int vi = 0; vi < 6; ++vi) {
        int i = tf_voigt_i[vi], j = tf_voigt_j[vi];
        t[3 * i + j] = t[3 * j + i] = v[vi];
    }
}

/* Inverse of a general 3 x 3 with determinant det. */
static void inverse3(const double a[9], double det, double inv[9])
{
    inv[0] = (a[4] * a[8] - a[5] * a[7]) / det;
    inv[1] = (a[2] * a[7] - a[1] * a[8]) / det;
    inv[2] = (a[1] * a[5] - a[2] * a[4]) / det;
    inv[3] = (a[5] * a[6] - a[3] * a[8]) / det;
    inv[4] = (a[0] * a[8] - a[2] * a[6]) / det;
    inv[5] = (a[2] * a[3] - a[0] * a[5]) / det;
    inv[6] = (a[3] * a[7] - a[4] * a[6]) / det;
    inv[7] = (a[1] * a[6] - a[0] * a[7]) / det;
    inv[8] = (a[0] * a[4] - a[1] * a[3]) / det;
}

/* J - 1 without the cancellation of det F - 1 (a bulk modulus fifty times
 * the shear one would turn it into the residual's rounding floor):
 * det(I + H) - 1 = tr H + ((tr H)^2 - tr(H H)) / 2 + det H; small strain:
 * tr H. */
static double jacobian_minus_one(const double F[9], int small)
{
    double H[9];
    for (int k = 0; k < 9; ++k) {
        H[k] = F[k] - (k % 4 == 0);
    }
    double tr = H[0] + H[4] + H[8];
    if (small) {
        return tr;
    }
    double hh = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            hh += H[3 * i + j] * H[3 * j + i];
        }
    }
    return tr + 0.5 * (tr * tr - hh) + tf_det3(H);
}

/* tr E = tr H + |H|^2 / 2 (Green-St. Venant), exact. */
static double green_trace(const double F[9])
{
    double tr = 0, hh = 0;
    for (int k = 0; k < 9; ++k) {
        double h = F[k] - (k % 4 == 0);
        tr += k % 4 == 0 ? h : 0;
        hh += h * h;
    }
    return tr + 0.5 * hh;
}

/* Pointwise part: F, the law, J - 1 and dJ (and h = F^-T G for the second
 * derivative of J) of every point of the cell.  Returns 0, or 1 with the
 * fault (det F <= 0). */
static int cell_points(const nl_solver *s, size_t c, const double *G, size_t m, double dt,
                       int tangent, cell_buf *b, nl_fault *fault)
{
    size_t np = s->np, m3 = 3 * m;
    for (size_t p = 0; p < np; ++p) {
        double *pt = b->pt + p * PT_STRIDE, *F = pt + PT_F;
        const double *Gp = G + 3 * p * m;
        /* one pass over each gradient row for the three displacement
         * components (the residual's hottest loop; each entry's sum is in
         * the same order as one entry at a time, so the same bits) */
        for (int bb = 0; bb < 3; ++bb) {
            double h0 = 0, h1 = 0, h2 = 0;
            const double *g = Gp + (size_t)bb * m, *dl = b->dl;
            for (size_t i = 0; i < m; ++i) {
                h0 += dl[3 * i] * g[i];
                h1 += dl[3 * i + 1] * g[i];
                h2 += dl[3 * i + 2] * g[i];
            }
            F[bb] = h0 + (bb == 0);
            F[3 + bb] = h1 + (bb == 1);
            F[6 + bb] = h2 + (bb == 2);
        }
        double det = tf_det3(F);
        const double *hold = s->hist + (c * np + p) * s->hb;
        double *hnew = s->hist_new + (c * np + p) * s->hb;
        const unsigned mat = nl_point_mat(s, c * np + p);
        pt[PT_LAMBDA] = s->lambda_m[mat];
        pt[PT_MAT] = mat;
        int rc = det > 0 ? tf_material_eval(&s->mats[mat], F, dt, hold, hnew, pt + PT_S,
                                            tangent ? pt + PT_C : NULL, NULL)
                         : TF_MAT_INVERTED;
        if (rc != TF_MAT_OK) {
            double w;
            fault->inverted = 1;
            fault->j = det;
            tf_cells_point(&s->sh.cells, c, p, fault->x, &w);
            return 1;
        }
        double *dj = b->dj + p * m3, *hv = b->hv + p * m3;
        pt[PT_J] = s->trace_volume ? green_trace(F) : jacobian_minus_one(F, s->small);
        double *cv = pt + PT_CV;
        cv[0] = cv[1] = cv[2] = 1; /* d tr E, d div u: c = (1, 1, 1, 0, 0, 0) */
        cv[3] = cv[4] = cv[5] = 0;
        if (s->trace_volume) { /* d tr E = (F G_i)_a */
            for (size_t i = 0; i < m; ++i) {
                for (size_t a = 0; a < 3; ++a) {
                    dj[3 * i + a] = F[3 * a] * Gp[i] + F[3 * a + 1] * Gp[m + i] +
                                    F[3 * a + 2] * Gp[2 * m + i];
                }
            }
        } else if (s->small) {
            for (size_t i = 0; i < m; ++i) {
                for (size_t a = 0; a < 3; ++a) {
                    dj[3 * i + a] = Gp[a * m + i];
                }
            }
        } else {
            double inv[9];
            inverse3(F, det, inv);
            for (int vi = 0; vi < 6; ++vi) { /* dJ = J C^-1 : dE, C^-1 = F^-1 F^-T */
                int i = tf_voigt_i[vi], j = tf_voigt_j[vi];
                cv[vi] = inv[3 * i] * inv[3 * j] + inv[3 * i + 1] * inv[3 * j + 1] +
                         inv[3 * i + 2] * inv[3 * j + 2];
            }
            for (size_t i = 0; i < m; ++i) {
                for (size_t a = 0; a < 3; ++a) {
                    double h = inv[a] * Gp[i] + inv[3 + a] * Gp[m + i] + inv[6 + a] * Gp[2 * m + i];
                    hv[3 * i + a] = h;
                    dj[3 * i + a] = det * h;
                }
            }
        }
    }
    return 0;
}

/* The volumetric correction's pressures q~ and their factor kappa = dq~/dq
 * (nl_assemble's header).  A cell an inclusion cuts averages J over each
 * material's points apart (as the linear B-bar, solvers/cell_stiffness.c):
 * Jbar_k over material k's points, with its own lambda_v. */
static void cell_correction(const nl_solver *s, size_t c, const double *w, double dt,
                            cell_buf *b)
{
    size_t np = s->np;
    double vol[1 + TF_INCLUSIONS_MAX] = {0}, jbar[1 + TF_INCLUSIONS_MAX] = {0};
    for (size_t p = 0; p < np; ++p) {
        const size_t k = (size_t)b->pt[p * PT_STRIDE + PT_MAT];
        vol[k] += w[p];
        jbar[k] += w[p] * b->pt[p * PT_STRIDE + PT_J];
    }
    for (size_t k = 0; k < s->n_mats; ++k) {
        jbar[k] = vol[k] > 0 ? jbar[k] / vol[k] : 0;
    }
    /* each material's relaxation over the step (a law with history) */
    double decay[1 + TF_INCLUSIONS_MAX], phi1[1 + TF_INCLUSIONS_MAX], phi2;
    for (size_t k = 0; s->relaxes && k < s->n_mats; ++k) {
        tf_relax_factors(dt / s->tau[k], &decay[k], &phi1[k], &phi2);
    }
    for (size_t p = 0; p < np; ++p) {
        double *pt = b->pt + p * PT_STRIDE;
        const size_t k = (size_t)pt[PT_MAT];
        double q = pt[PT_LAMBDA] * (jbar[k] - pt[PT_J]);
        pt[PT_Q] = q;
        pt[PT_KAPPA] = 1;
        if (s->relaxes && pt[PT_LAMBDA] != 0) {
            const double *hold = s->hist + (c * np + p) * s->hb + s->nh;
            double *hnew = s->hist_new + (c * np + p) * s->hb + s->nh;
            const double g = s->g_inf[k];
            double h = decay[k] * hold[1] + phi1[k] * (q - hold[0]);
            hnew[0] = q;
            hnew[1] = h;
            pt[PT_Q] = g * q + (1 - g) * h;
            pt[PT_KAPPA] = g + (1 - g) * phi1[k];
        }
    }
}

/* The cell's internal forces fl (3 m). */
static void cell_forces(const nl_solver *s, const double *G, const double *w, size_t m,
                        cell_buf *b, double *fl)
{
    size_t np = s->np, m3 = 3 * m;
    memset(fl, 0, m3 * sizeof *fl);
    for (size_t p = 0; p < np; ++p) {
        double *pt = b->pt + p * PT_STRIDE, St[9], *P = pt + PT_P;
        const double *F = pt + PT_F, *Gp = G + 3 * p * m, *dj = b->dj + p * m3;
        tensor_of_voigt(pt + PT_S, St);
        if (s->small) {
            memcpy(P, St, sizeof St);
        } else {
            tf_matmul3(F, St, P);
        }
        double wq = w[p] * pt[PT_Q];
        for (size_t i = 0; i < m; ++i) {
            for (size_t a = 0; a < 3; ++a) {
                double v = P[3 * a] * Gp[i] + P[3 * a + 1] * Gp[m + i] + P[3 * a + 2] * Gp[2 * m + i];
                fl[3 * i + a] += w[p] * v + wq * dj[3 * i + a];
            }
        }
    }
}

/* The point's 6 x 6 matrix of the material part: C minus the volumetric
 * correction's pointwise term kappa lambda_v j^2 c c^T (d theta = j c . dE,
 * j = J for theta = J - 1 at finite strain, else 1), so that one product
 * gives both. */
static void material_matrix(const nl_solver *s, const double *pt, double ce[36])
{
    const double *C = pt + PT_C, *cv = pt + PT_CV;
    double j = s->small || s->trace_volume ? 1 : 1 + pt[PT_J];
    double f = pt[PT_LAMBDA] * pt[PT_KAPPA] * j * j;
    for (int k = 0; k < 36; ++k) {
        ce[k] = C[k] - f * cv[k / 6] * cv[k % 6];
    }
}

/* Cholesky of a symmetric 6 x 6 (lower, in place).  Returns 0, or -1 when
 * it is not positive definite. */
static int cholesky6(double a[36])
{
    for (int j = 0; j < 6; ++j) {
        double d = a[6 * j + j];
        for (int k = 0; k < j; ++k) {
            d -= a[6 * j + k] * a[6 * j + k];
        }
        if (!(d > 0)) {
            return -1;
        }
        d = sqrt(d);
        a[6 * j + j] = d;
        for (int i = j + 1; i < 6; ++i) {
            double v = a[6 * i + j];
            for (int k = 0; k < j; ++k) {
                v -= a[6 * i + k] * a[6 * j + k];
            }
            a[6 * i + j] = v / d;
        }
    }
    return 0;
}

/* B (Voigt rows of dE per DOF) of every point, stacked in bs
 * [(6p + I) + 6 np (3i + a)]; with a positive definite material matrix at
 * every point (symmetric laws) bs is replaced by L^T B sqrt(w) (C = L L^T)
 * and the return is 1: K = bs^T bs.  Otherwise cbs holds w C B and the
 * return is 0: K = bs^T cbs. */
static int stack_b(const nl_solver *s, const double *G, const double *w, size_t m, cell_buf *b)
{
    size_t np = s->np, ld = 6 * np;
    int spd = !s->unsym;
    double ce[36 * 27], *cep = np <= 27 ? ce : NULL;
    for (size_t p = 0; p < np; ++p) {
        double one[36], *c = cep ? cep + 36 * p : one;
        material_matrix(s, b->pt + p * PT_STRIDE, c);
        if (spd && cep) {
            double l[36];
            memcpy(l, c, sizeof l);
            spd = cholesky6(l) == 0;
        }
    }
    spd = spd && cep;
    for (size_t p = 0; p < np; ++p) {
        const double *pt = b->pt + p * PT_STRIDE, *F = pt + PT_F;
        const double *Gp = G + 3 * p * m;
        double c[36], sw = sqrt(w[p]);
        if (cep) {
            memcpy(c, cep + 36 * p, sizeof c);
        } else {
            material_matrix(s, pt, c);
        }
        if (spd) {
            cholesky6(c);
        }
        for (size_t i = 0; i < m; ++i) {
            for (size_t a = 0; a < 3; ++a) {
                double col[6];
                for (int vi = 0; vi < 6; ++vi) {
                    size_t bi = (size_t)tf_voigt_i[vi], gi = (size_t)tf_voigt_j[vi];
                    double fb = s->small ? (a == bi) : F[3 * a + bi];
                    double fg = s->small ? (a == gi) : F[3 * a + gi];
                    col[vi] = bi == gi ? fb * Gp[bi * m + i] : fb * Gp[gi * m + i] + fg * Gp[bi * m + i];
                }
                double *bcol = b->bs + ld * (3 * i + a) + 6 * p;
                double *ccol = b->cbs + ld * (3 * i + a) + 6 * p;
                for (int vi = 0; vi < 6; ++vi) {
                    double v = 0;
                    if (spd) { /* (L^T col)_vi = sum_{k >= vi} L[k][vi] col[k] */
                        for (int k = vi; k < 6; ++k) {
                            v += c[6 * k + vi] * col[k];
                        }
                        bcol[vi] = sw * v;
                    } else {
                        for (int vj = 0; vj < 6; ++vj) {
                            v += c[6 * vi + vj] * col[vj];
                        }
                        bcol[vi] = col[vi];
                        ccol[vi] = w[p] * v;
                    }
                }
            }
        }
    }
    return spd;
}

/* Geometric stiffness delta_ab G_i . S G_j into kc (3m x 3m). */
static void geometric(const nl_solver *s, const double *G, const double *w, size_t m,
                      cell_buf *b, double *kc)
{
    size_t np = s->np, ld = 3 * np, m3 = 3 * m;
    for (size_t p = 0; p < np; ++p) {
        double St[9];
        tensor_of_voigt(b->pt + p * PT_STRIDE + PT_S, St);
        if (s->trace_volume) { /* the correction's second derivative: q~ tr(dF1^T dF2) */
            double q = b->pt[p * PT_STRIDE + PT_Q];
            St[0] += q;
            St[4] += q;
            St[8] += q;
        }
        const double *Gp = G + 3 * p * m;
        for (size_t i = 0; i < m; ++i) {
            for (size_t be = 0; be < 3; ++be) {
                b->gs[(3 * p + be) + ld * i] = Gp[be * m + i];
                b->sgs[(3 * p + be) + ld * i] =
                    w[p] * (St[3 * be] * Gp[i] + St[3 * be + 1] * Gp[m + i] + St[3 * be + 2] * Gp[2 * m + i]);
            }
        }
    }
    cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, (int)m, (int)m, (int)ld, 1.0, b->gs,
                (int)ld, b->sgs, (int)ld, 0.0, b->ms, (int)m);
    for (size_t j = 0; j < m; ++j) {
        for (size_t i = 0; i < m; ++i) {
            double v = b->ms[i + m * j];
            for (size_t a = 0; a < 3; ++a) {
                kc[(3 * i + a) + m3 * (3 * j + a)] += v;
            }
        }
    }
}

/* The volumetric correction's tangent into kc: per material of the cell
 * (cell_correction), f s_k s_k^T / V_k, s_k the sum of w dJ over its points. */
static void correction_tangent(const nl_solver *s, const double *w, size_t m, cell_buf *b,
                               double *kc)
{
    size_t np = s->np, m3 = 3 * m;
    double kappa = b->pt[PT_KAPPA];
    unsigned done = 0; /* materials added, a bit each */
    for (size_t first = 0; first < np; ++first) {
        const unsigned k = (unsigned)b->pt[first * PT_STRIDE + PT_MAT];
        if (done & (1u << k)) {
            continue;
        }
        done |= 1u << k;
        double vol = 0;
        memset(b->sv, 0, m3 * sizeof *b->sv);
        for (size_t p = first; p < np; ++p) {
            if ((unsigned)b->pt[p * PT_STRIDE + PT_MAT] != k) {
                continue;
            }
            const double *dj = b->dj + p * m3;
            vol += w[p];
            for (size_t q = 0; q < m3; ++q) {
                b->sv[q] += w[p] * dj[q];
            }
        }
        /* f s s^T / V; the pointwise - f sum_g w dJ dJ^T is in the material
         * matrix (material_matrix) */
        double f = kappa * s->lambda_m[k];
        cblas_dger(CblasColMajor, (int)m3, (int)m3, f / vol, b->sv, 1, b->sv, 1, kc, (int)m3);
    }
    if (s->small || s->trace_volume) {
        return;
    }
    /* sum_g w q~ J (h h^T - blockwise transpose), the second derivative of J */
    for (size_t p = 0; p < np; ++p) {
        const double *pt = b->pt + p * PT_STRIDE, *hv = b->hv + p * m3;
        double cp = w[p] * pt[PT_Q] * (1 + pt[PT_J]);
        for (size_t q = 0; q < m3; ++q) {
            b->hs[p + np * q] = hv[q];
            b->hc[p + np * q] = cp * hv[q];
        }
    }
    double *o = b->o;
    cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, (int)m3, (int)m3, (int)np, 1.0, b->hs,
                (int)np, b->hc, (int)np, 0.0, o, (int)m3);
    for (size_t j = 0; j < m; ++j) {
        for (size_t i = 0; i < m; ++i) {
            for (size_t bb = 0; bb < 3; ++bb) {
                for (size_t a = 0; a < 3; ++a) {
                    kc[(3 * i + a) + m3 * (3 * j + bb)] +=
                        o[(3 * i + a) + m3 * (3 * j + bb)] - o[(3 * i + bb) + m3 * (3 * j + a)];
                }
            }
        }
    }
}

/* The cell's tangent kc (3m x 3m, column major, full). */
static void cell_tangent(const nl_solver *s, const double *G, const double *w, size_t m,
                         cell_buf *b, double *kc)
{
    size_t m3 = 3 * m, ld = 6 * s->np;
    if (stack_b(s, G, w, m, b)) {
        cblas_dsyrk(CblasColMajor, CblasLower, CblasTrans, (int)m3, (int)ld, 1.0, b->bs, (int)ld,
                    0.0, kc, (int)m3);
        for (size_t j = 0; j < m3; ++j) { /* the upper triangle too (add_split reads both) */
            for (size_t i = j + 1; i < m3; ++i) {
                kc[j + m3 * i] = kc[i + m3 * j];
            }
        }
    } else {
        cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, (int)m3, (int)m3, (int)ld, 1.0,
                    b->bs, (int)ld, b->cbs, (int)ld, 0.0, kc, (int)m3);
    }
    if (!s->small) {
        geometric(s, G, w, m, b, kc);
    }
    if (s->vol_corr) {
        correction_tangent(s, w, m, b, kc);
    }
}

/* Adds a full dense matrix over ascending nodes idx (3n x 3n) to the
 * symmetric part (k) and, when kskew is not NULL, the skew part.  The
 * entries are found by walking each column node's block list (ascending,
 * as idx is) rather than by a binary search per entry: this runs serially
 * between the parallel batches. */
static void add_split(const nl_solver *s, const uint32_t *idx, size_t n, const double *kc,
                      double *kx, double *kskew)
{
    const tf_csc *k = &s->k;
    const tf_nodesets *bp = &s->bp;
    size_t dim = 3 * n;
    for (size_t j = 0; j < n; ++j) {
        size_t b = idx[j], q = bp->ptr[b], end = bp->ptr[b + 1];
        for (size_t i = j; i < n; ++i) {
            size_t a = idx[i], at = q;
            while (at < end && bp->nodes[at] != a) {
                at++;
            }
            if (at == end) {
                continue; /* (the pattern holds every pair of a cell) */
            }
            q = at;
            for (size_t bb = 0; bb < 3; ++bb) {
                size_t cj = 3 * j + bb;
                for (size_t aa = a == b ? bb : 0; aa < 3; ++aa) {
                    size_t e = tf_sparsity_entry(k, a, b, q - bp->ptr[b], aa, bb), ri = 3 * i + aa;
                    double lo = kc[ri + dim * cj], up = kc[cj + dim * ri];
                    kx[e] += 0.5 * (lo + up);
                    if (kskew) {
                        kskew[e] += 0.5 * (lo - up);
                    }
                }
            }
        }
    }
}

/* ---- weak boundary terms ---- */

/* u_h - scale ubar at a boundary point, and F there. */
static void boundary_state(const nl_solver *s, size_t q, const double *d, double scale,
                           double g[3], double F[9])
{
    const tf_bpoint *bp = &s->bnd.pt[q];
    size_t n = s->bptr[q + 1] - s->bptr[q], o = s->bptr[q];
    const double *phi = s->bphi + o, *dphi = s->bdphi + 3 * o;
    double u[3] = {0, 0, 0};
    for (int k = 0; k < 9; ++k) {
        F[k] = k % 4 == 0;
    }
    for (size_t i = 0; i < n; ++i) {
        const double *di = d + 3 * (size_t)s->bidx[o + i];
        for (int a = 0; a < 3; ++a) {
            u[a] += phi[i] * di[a];
            for (int c = 0; c < 3; ++c) {
                F[3 * a + c] += di[a] * dphi[(size_t)c * n + i];
            }
        }
    }
    for (int a = 0; a < 3; ++a) {
        g[a] = (bp->mask >> a) & 1u ? u[a] - scale * bp->ubar[a] : 0;
    }
}

/* A = dP/dF (81: A[27 a + 9 B + 3 b + D]) from F, S, C (finite) or C
 * (small: P = sigma). */
static void first_elasticity(const nl_solver *s, const double F[9], const double Sv[6],
                             const double Cv[36], double A[81])
{
    static const int v[9] = {0, 5, 4, 5, 1, 3, 4, 3, 2}; /* Voigt index of (i, j) */
    double St[9];
    tensor_of_voigt(Sv, St);
    for (int a = 0; a < 3; ++a) {
        for (int B = 0; B < 3; ++B) {
            for (int b = 0; b < 3; ++b) {
                for (int D = 0; D < 3; ++D) {
                    double x;
                    if (s->small) {
                        x = Cv[6 * v[3 * a + B] + v[3 * b + D]];
                    } else {
                        x = a == b ? St[3 * B + D] : 0;
                        for (int vi = 0; vi < 3; ++vi) {
                            for (int vj = 0; vj < 3; ++vj) {
                                x += F[3 * a + vi] * F[3 * b + vj] * Cv[6 * v[3 * vi + B] + v[3 * vj + D]];
                            }
                        }
                    }
                    A[27 * a + 9 * B + 3 * b + D] = x;
                }
            }
        }
    }
}

/* Nitsche's terms of one point: residual into r, tangent (without the
 * constant beta part, which is in kbc) into the dense kl.  Returns 0, or 1
 * with the fault. */
static int nitsche_point(nl_solver *s, size_t q, const double *d, const nl_target *t, double dt,
                         int tangent, double *r, double *kl, double *tv, nl_fault *fault)
{
    const tf_bpoint *bp = &s->bnd.pt[q];
    size_t n = s->bptr[q + 1] - s->bptr[q], o = s->bptr[q], dim = 3 * n;
    const double *phi = s->bphi + o, *dphi = s->bdphi + 3 * o, *N = bp->n;
    double g[3], F[9], Sv[6], Cv[36], A[81], St[9], P[9], tr[3];
    boundary_state(s, q, d, t->scale, g, F);
    double det = tf_det3(F);
    int rc = det > 0 ? tf_material_eval(&s->mats[nl_bpoint_mat(s, q)], F, dt, s->bhist + q * s->nh,
                                        s->bhist_new + q * s->nh, Sv, Cv, NULL)
                     : TF_MAT_INVERTED;
    if (rc != TF_MAT_OK) {
        fault->inverted = 1;
        fault->j = det;
        memcpy(fault->x, bp->x, sizeof fault->x);
        return 1;
    }
    tensor_of_voigt(Sv, St);
    if (s->small) {
        memcpy(P, St, sizeof P);
    } else {
        tf_matmul3(F, St, P);
    }
    first_elasticity(s, F, Sv, Cv, A);
    for (int a = 0; a < 3; ++a) {
        tr[a] = (bp->mask >> a) & 1u ? P[3 * a] * N[0] + P[3 * a + 1] * N[1] + P[3 * a + 2] * N[2]
                                     : 0;
    }
    /* tv[(3 i + a) 3 + b] = (dP(i, a) N)_b, masked: the traction's variation */
    for (size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                double x = 0;
                for (int B = 0; B < 3; ++B) {
                    for (int C = 0; C < 3; ++C) {
                        x += A[27 * b + 9 * B + 3 * a + C] * dphi[(size_t)C * n + i] * N[B];
                    }
                }
                tv[9 * i + 3 * (size_t)a + (size_t)b] = (bp->mask >> b) & 1u ? x : 0;
            }
        }
    }
    double w = bp->w, beta = s->base.opts.bc == TF_BC_NITSCHE ? s->bc_factor : 0;
    for (size_t i = 0; i < n; ++i) {
        double *ri = r + 3 * (size_t)s->bidx[o + i];
        for (int a = 0; a < 3; ++a) {
            const double *ti = tv + 9 * i + 3 * (size_t)a;
            ri[a] += w * (-phi[i] * tr[a] - (ti[0] * g[0] + ti[1] * g[1] + ti[2] * g[2]) +
                          beta * phi[i] * g[a]);
        }
    }
    for (size_t j = 0; tangent && j < n; ++j) {
        for (int b = 0; b < 3; ++b) {
            const double *tj = tv + 9 * j + 3 * (size_t)b;
            for (size_t i = 0; i < n; ++i) {
                for (int a = 0; a < 3; ++a) {
                    kl[(3 * i + (size_t)a) + dim * (3 * j + (size_t)b)] =
                        -w * (phi[i] * tj[a] + tv[9 * i + 3 * (size_t)a + (size_t)b] * phi[j]);
                }
            }
        }
    }
    return 0;
}

/* Penalty: alpha int phi_i S (u_h - ubar) (its tangent is kbc). */
static void penalty_point(const nl_solver *s, size_t q, const double *d, double scale, double *r)
{
    size_t n = s->bptr[q + 1] - s->bptr[q], o = s->bptr[q];
    double g[3], F[9], f = s->bnd.pt[q].w * s->bc_factor;
    boundary_state(s, q, d, scale, g, F);
    for (size_t i = 0; i < n; ++i) {
        double *ri = r + 3 * (size_t)s->bidx[o + i];
        for (int a = 0; a < 3; ++a) {
            ri[a] += f * s->bphi[o + i] * g[a];
        }
    }
}

static int boundary_terms(nl_solver *s, const double *d, const nl_target *t, double dt,
                          int tangent, double *r, nl_fault *fault)
{
    if (s->base.opts.bc == TF_BC_PENALTY) {
        for (size_t q = 0; q < s->bnd.n; ++q) {
            penalty_point(s, q, d, t->scale, r);
        }
        return 0;
    }
    size_t cap = 0;
    double *kl = NULL, *tv = NULL;
    int rc = 0;
    for (size_t q = 0; q < s->bnd.n && rc == 0; ++q) {
        size_t n = s->bptr[q + 1] - s->bptr[q];
        if (n > cap) {
            cap = n;
            free(kl);
            free(tv);
            kl = malloc(9 * cap * cap * sizeof *kl);
            tv = malloc(9 * cap * sizeof *tv);
            if (kl == NULL || tv == NULL) {
                rc = -1;
                break;
            }
        }
        rc = nitsche_point(s, q, d, t, dt, tangent, r, kl, tv, fault);
        if (rc == 0 && tangent) {
            add_split(s, s->bidx + s->bptr[q], n, kl, s->k.x, s->kskew);
        }
    }
    free(kl);
    free(tv);
    if (rc < 0) {
        return tf_fail(s->base.ctx, "out of memory");
    }
    return rc;
}

/* ---- the whole system ---- */

typedef struct pass {
    nl_solver *s;
    const double *d;
    double dt;
    int tangent;
    const unsigned char *only; /* cells to assemble (NULL: all) */
    double *fl, *kc; /* batch slices */
    size_t batch;
    size_t fstride, kstride;
} pass;

static int cell_work(const pass *ps, size_t c, cell_buf *b, double *fl, double *kc,
                     nl_fault *fault)
{
    const nl_solver *s = ps->s;
    const uint32_t *set = s->cs.nodes + s->cs.ptr[c];
    size_t m = s->cs.ptr[c + 1] - s->cs.ptr[c];
    const double *G = s->grad + s->gptr[c], *w = s->wts + c * s->np;
    for (size_t i = 0; i < m; ++i) {
        memcpy(b->dl + 3 * i, ps->d + 3 * (size_t)set[i], 3 * sizeof *b->dl);
    }
    if (cell_points(s, c, G, m, ps->dt, ps->tangent, b, fault) != 0) {
        return 1;
    }
    cell_correction(s, c, w, ps->dt, b);
    cell_forces(s, G, w, m, b, fl);
    if (ps->tangent) {
        cell_tangent(s, G, w, m, b, kc);
    }
    return 0;
}

static int all_cells(pass *ps, double *fint, nl_fault *fault)
{
    nl_solver *s = ps->s;
    size_t nc = s->ncell, failed = SIZE_MAX;
    int nt = tf_ctx_threads(s->base.ctx), oom = 0;
    cell_buf *bufs = calloc((size_t)nt, sizeof *bufs);
    for (int t = 0; bufs && t < nt; ++t) {
        oom |= buf_init(&bufs[t], s->np, s->maxm);
    }
    if (bufs == NULL || oom) {
        for (int t = 0; bufs && t < nt; ++t) {
            buf_free(&bufs[t]);
        }
        free(bufs);
        return tf_fail(s->base.ctx, "out of memory");
    }
    openblas_set_num_threads(1);
    for (size_t start = 0; start < nc && failed == SIZE_MAX; start += ps->batch) {
        size_t end = start + ps->batch < nc ? start + ps->batch : nc;
#pragma omp parallel for num_threads(nt) schedule(dynamic, 1)
        for (size_t c = start; c < end; ++c) {
            nl_fault f = {0};
            if (ps->only && !ps->only[c]) {
                continue;
            }
            /* no tangent: kc is NULL, and NULL + 0 is undefined in C */
            double *kc = ps->kc ? ps->kc + (c - start) * ps->kstride : NULL;
            if (cell_work(ps, c, &bufs[omp_get_thread_num()], ps->fl + (c - start) * ps->fstride,
                          kc, &f) != 0) {
#pragma omp critical(tf_nl_fault)
                if (c < failed) {
                    failed = c;
                    *fault = f;
                }
            }
        }
        for (size_t c = start; c < end && failed == SIZE_MAX; ++c) {
            if (ps->only && !ps->only[c]) {
                continue;
            }
            const uint32_t *set = s->cs.nodes + s->cs.ptr[c];
            size_t m = s->cs.ptr[c + 1] - s->cs.ptr[c];
            const double *fl = ps->fl + (c - start) * ps->fstride;
            for (size_t i = 0; i < m; ++i) {
                for (size_t a = 0; a < 3; ++a) {
                    fint[3 * (size_t)set[i] + a] += fl[3 * i + a];
                }
            }
            if (ps->tangent) {
                add_split(s, set, m, ps->kc + (c - start) * ps->kstride, s->k.x, s->kskew);
            }
        }
    }
    for (int t = 0; t < nt; ++t) {
        buf_free(&bufs[t]);
    }
    free(bufs);
    return failed == SIZE_MAX ? 0 : 1;
}

/* The cells of ps (forces into fi, the tangent into s->k when asked) in
 * batches.  Returns as all_cells. */
static int cells_pass(pass *ps, double *fi, nl_fault *fault)
{
    nl_solver *s = ps->s;
    size_t n3 = 3 * s->sh.cloud->n, m = s->maxm;
    ps->batch = s->ncell;
    ps->fstride = 3 * m;
    ps->kstride = ps->tangent ? 9 * m * m : 0;
    if (ps->tangent) {
        double fit = TANGENT_BATCH_BYTES / (8.0 * (double)ps->kstride);
        ps->batch = fit < 32 ? 32 : fit > (double)s->ncell ? s->ncell : (size_t)fit;
    }
    ps->fl = malloc(ps->batch * ps->fstride * sizeof *ps->fl);
    ps->kc = ps->tangent ? malloc(ps->batch * ps->kstride * sizeof *ps->kc) : NULL;
    if (ps->fl == NULL || (ps->tangent && ps->kc == NULL)) {
        free(ps->fl);
        free(ps->kc);
        return tf_fail(s->base.ctx, "out of memory for the cell matrices");
    }
    memset(fi, 0, n3 * sizeof *fi);
    if (ps->only) { /* the patch's cells add to A's columns only (nl_patch.c reads them) */
        for (size_t j = 0; j < s->k.n; ++j) {
            for (int q = s->k.p[j]; s->patch.dof[j] && q < s->k.p[j + 1]; ++q) {
                s->k.x[q] = s->kbc ? s->kbc[q] : 0;
            }
        }
    } else if (ps->tangent) {
        if (s->kbc) {
            memcpy(s->k.x, s->kbc, s->k.nnz * sizeof *s->k.x);
        } else {
            memset(s->k.x, 0, s->k.nnz * sizeof *s->k.x);
        }
        if (s->kskew) {
            memset(s->kskew, 0, s->k.nnz * sizeof *s->kskew);
        }
    }
    int rc = all_cells(ps, fi, fault);
    free(ps->fl);
    free(ps->kc);
    return rc;
}

static int all_zero(const double *x, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        if (x[i] != 0) {
            return 0;
        }
    }
    return 1;
}

/* The state nl_reset leaves, at the time step of a static solve: every
 * static case's first tangent (when nothing prescribed differs from 0). */
static int at_rest(const nl_solver *s, const double *d, double dt)
{
    return dt == s->dt_relaxed && all_zero(d, 3 * s->sh.cloud->n) &&
           all_zero(s->hist, s->ncell * s->np * s->hb) && all_zero(s->bhist, s->bnd.n * s->nh);
}

int nl_assemble(nl_solver *s, const double *d, const nl_target *t, double dt, int tangent,
                double *r, double *fint, nl_fault *fault)
{
    size_t n3 = 3 * s->sh.cloud->n;
    double t0 = omp_get_wtime();
    pass ps = {.s = s, .d = d, .dt = dt, .tangent = tangent};
    double *fi = fint ? fint : s->fint;
    int rc = cells_pass(&ps, fi, fault);
    if (rc == 0) {
        memcpy(r, fi, n3 * sizeof *r);
        rc = s->weak ? boundary_terms(s, d, t, dt, tangent, r, fault) : 0;
    }
    double el = omp_get_wtime() - t0;
    if (tangent) {
        s->k_rest = rc == 0 && at_rest(s, d, dt);
        s->st.tangents++;
        s->st.t_tangent += el;
    } else {
        s->st.residuals++;
        s->st.t_residual += el;
    }
    return rc;
}

int nl_assemble_patch(nl_solver *s, const double *d, double dt, nl_fault *fault)
{
    double t0 = omp_get_wtime();
    pass ps = {.s = s, .d = d, .dt = dt, .tangent = 1, .only = s->patch.cell};
    double *fi = malloc(3 * s->sh.cloud->n * sizeof *fi); /* (the forces are not kept) */
    if (fi == NULL) {
        return tf_fail(s->base.ctx, "out of memory");
    }
    int rc = cells_pass(&ps, fi, fault);
    free(fi);
    s->st.t_patch += omp_get_wtime() - t0;
    return rc;
}

void nl_external(const nl_solver *s, const nl_target *t, double *f)
{
    size_t n3 = 3 * s->sh.cloud->n;
    for (size_t q = 0; q < n3; ++q) {
        f[q] = t->scale * s->f0[q];
    }
    if (t->contact >= 0) {
        const double *b = s->basis + 3 * n3 * (size_t)t->contact;
        for (size_t q = 0; q < n3; ++q) {
            f[q] += b[q] * t->force[0] + b[n3 + q] * t->force[1] + b[2 * n3 + q] * t->force[2];
        }
    }
}

/* The support's force on the body from one fixed region, weak form:
 * minus the sum over the nodes of the region's boundary terms, i.e.
 * sum_q w (S P N - beta S g) (Nitsche) or -sum_q w alpha S g (penalty),
 * at the state (d, histories) just committed: the laws evaluated with
 * dt = 0 from the committed history give its stress back. */
int nl_region_force(nl_solver *s, size_t region, double force[3])
{
    force[0] = force[1] = force[2] = 0;
    for (size_t q = 0; q < s->bnd.n; ++q) {
        const tf_bpoint *bp = &s->bnd.pt[q];
        if (bp->region != region) {
            continue;
        }
        double g[3], F[9], Sv[6], St[9], P[9];
        boundary_state(s, q, s->d, s->at.scale, g, F);
        double f = s->base.opts.bc == TF_BC_PENALTY ? s->bc_factor : 0;
        if (s->base.opts.bc == TF_BC_NITSCHE) {
            double *h = s->bhist + q * s->nh;
            if (tf_material_eval(&s->mats[nl_bpoint_mat(s, q)], F, 0, h, s->bhist_new + q * s->nh,
                                 Sv, NULL, NULL) !=
                TF_MAT_OK) {
                return tf_fail(s->base.ctx, "J <= 0 at the boundary point (%g, %g, %g) mm",
                               bp->x[0], bp->x[1], bp->x[2]);
            }
            tensor_of_voigt(Sv, St);
            if (s->small) {
                memcpy(P, St, sizeof P);
            } else {
                tf_matmul3(F, St, P);
            }
            f = s->bc_factor;
            for (int a = 0; a < 3; ++a) {
                if ((bp->mask >> a) & 1u) {
                    force[a] += bp->w * (P[3 * a] * bp->n[0] + P[3 * a + 1] * bp->n[1] +
                                         P[3 * a + 2] * bp->n[2]);
                }
            }
        }
        for (int a = 0; a < 3; ++a) {
            force[a] -= bp->w * f * g[a];
        }
    }
    return 0;
}
