/*
 * colloc_force.c — elastic forces of the particles (seed 004 eqs 4, 10-12).
 *
 * The stored energy is a sum over particles (nodal integration):
 *
 *   U = sum_i v_i W(F_i) + 1/2 kv v_i (det F_i - 1)^2 + U_res,i,
 *   F_i = I + sum_k (u_k - u_i) g_ik^T                      (colloc_mls.c)
 *
 * W the law's energy density (SVK: eqs 4-5, 10), the second term eq 12
 * (Müller et al.'s volume term; the seed writes it without v_i, which makes
 * kv depend on the particle size: with v_i it is a modulus, MPa).  The
 * force is f = -dU/du (eq 11): with P_i = dW/dF = F_i S_i (first
 * Piola-Kirchhoff; the law's stress itself for a small-strain law),
 *
 *   f_k = -sum_{i: k in N_i} v_i P_i g_ik  +  v_k P_k d_k,   d_k = sum_j g_kj.
 *
 * U_res is ours (the seed has no such term): nodal integration sees a
 * particle's deformation only through its MLS fit, and a displacement that
 * the fit cannot see (on a regular grid, neighbours moving in a
 * checkerboard) costs no energy — a zero-energy mode that a concentrated
 * load excites without bound.  U_res penalises what the fit leaves over,
 * the residual of eq 7 itself:
 *
 *   U_res,i = stab mu v_i (sum_k w_ik |r_ik|^2) / (sum_k w_ik |X_ik|^2),
 *   r_ik = x_k - x_i - F_i X_ik,
 *
 * objective (r turns with the body), zero for every linear field (so the
 * patch test is untouched) and O(h^2) for smooth ones.  Because F_i
 * minimises sum_k w_ik |r_ik|^2 (eq 9), dU_res/dF_i = 0 and its force is
 * just f_k = -beta_i w_ik r_ik on each neighbour, +beta_i sum_k w_ik r_ik
 * on i (beta_i = 2 stab mu v_i / sum_k w_ik |X_ik|^2).  It is in the spirit
 * of Ganzenmüller's hourglass control for SPH (2015), not a copy of it.
 *
 * Two phases, both parallel over particles and each writing only its own
 * particle's values: phase 1 computes F_i, P_i and what particle i sends;
 * phase 2 lets each particle gather from the particles whose supports hold
 * it, in ascending order.  Since g_ik = A_i^-1 y_ik (y_ik = w_ik X_ik), the
 * stress and residual forces of pair (i, k) combine into one 3 x 3 matrix
 * per particle, Q_i = v_i P_i A_i^-1 - beta_i G_i:
 *
 *   force on k from i:  -Q_i y_ik + beta_i w_ik (u_i - u_k),
 *   on i from itself:    Q_i s_i + beta_i sum_k w_ik (u_k - u_i),
 *
 * s_i = sum_k y_ik: 12 multiply-adds per pair in each phase.
 */
#include "solvers/collocation/colloc_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "materials/kinematics.h"

/* a b for 3 x 3 matrices: tf_matmul3's operations in its order (the same
 * bits), inlined because the step calls it three times per particle. */
static inline void mul3(const double a[9], const double b[9], double ab[9])
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            ab[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
        }
    }
}

/* Voigt stress (tensor components) -> symmetric tensor. */
static void voigt_to_tensor(const double v[6], double t[9])
{
    t[0] = v[0];
    t[4] = v[1];
    t[8] = v[2];
    t[5] = t[7] = v[3];
    t[2] = t[6] = v[4];
    t[1] = t[3] = v[5];
}

/* P += kv (J - 1) cof F (eq 12; d det F / dF = cof F); returns its energy
 * density 1/2 kv (J - 1)^2. */
static double volume_term(double kv, const double F[9], double P[9])
{
    double cof[9] = {F[4] * F[8] - F[5] * F[7], F[5] * F[6] - F[3] * F[8],
                     F[3] * F[7] - F[4] * F[6], F[2] * F[7] - F[1] * F[8],
                     F[0] * F[8] - F[2] * F[6], F[1] * F[6] - F[0] * F[7],
                     F[1] * F[5] - F[2] * F[4], F[2] * F[3] - F[0] * F[5],
                     F[0] * F[4] - F[1] * F[3]};
    double j = F[0] * cof[0] + F[1] * cof[1] + F[2] * cof[2];
    for (int k = 0; k < 9; ++k) {
        P[k] += kv * (j - 1) * cof[k];
    }
    return 0.5 * kv * (j - 1) * (j - 1);
}

/* Energy of particle i's residual term (only when the energy is asked). */
static double residual_energy(const tf_colloc *c, size_t i, const double *u, const double G[9])
{
    double e = 0;
    const double *ui = u + 3 * i, *xi = c->X + 3 * i;
    for (uint32_t p = c->start[i]; p < c->start[i + 1]; ++p) {
        size_t k = c->nbr[p];
        double x[3], r2 = 0;
        for (int a = 0; a < 3; ++a) {
            x[a] = c->X[3 * k + a] - xi[a];
        }
        for (int a = 0; a < 3; ++a) {
            double r = u[3 * k + a] - ui[a] - (G[3 * a] * x[0] + G[3 * a + 1] * x[1] +
                                               G[3 * a + 2] * x[2]);
            r2 += r * r;
        }
        e += c->w[p] * r2;
    }
    return 0.5 * c->beta[i] * e;
}

/* G_i = B_i A_i^-1, B_i = sum_k (u_k - u_i) y_ik^T (colloc_mls.c), and
 * q_i = sum_k w_ik (u_k - u_i).  Two passes over the pairs (rows x, y of
 * B and q, then row z): twelve sums at once do not fit the 16 registers,
 * and the spilled ones made the loop wait on memory (perf: 35 % of a step);
 * each sum keeps its order, so the bits are those of one pass. */
static void gradient(const tf_colloc *c, size_t i, const double *u, double G[9], double q[3])
{
    const double *ui = u + 3 * i, *yw = c->yw;
    const uint32_t *nbr = c->nbr;
    uint32_t p0 = c->start[i], p1 = c->start[i + 1];
    double b0 = 0, b1 = 0, b2 = 0, b3 = 0, b4 = 0, b5 = 0, q0 = 0, q1 = 0;
    for (uint32_t p = p0; p < p1; ++p) {
        const double *uk = u + 3 * (size_t)nbr[p], *y = yw + 4 * (size_t)p;
        double du0 = uk[0] - ui[0], du1 = uk[1] - ui[1];
        b0 += du0 * y[0];
        b1 += du0 * y[1];
        b2 += du0 * y[2];
        b3 += du1 * y[0];
        b4 += du1 * y[1];
        b5 += du1 * y[2];
        q0 += y[3] * du0;
        q1 += y[3] * du1;
    }
    double b6 = 0, b7 = 0, b8 = 0, q2 = 0;
    for (uint32_t p = p0; p < p1; ++p) {
        const double *uk = u + 3 * (size_t)nbr[p], *y = yw + 4 * (size_t)p;
        double du2 = uk[2] - ui[2];
        b6 += du2 * y[0];
        b7 += du2 * y[1];
        b8 += du2 * y[2];
        q2 += y[3] * du2;
    }
    double B[9] = {b0, b1, b2, b3, b4, b5, b6, b7, b8};
    q[0] = q0;
    q[1] = q1;
    q[2] = q2;
    mul3(B, c->ainv + 9 * i, G);
}

/* S = lambda tr(E) I + 2 mu E of a HOOKE material at finite strain
 * (St. Venant-Kirchhoff's form, seed 004 eqs 4-5) for the step, without
 * the call through tf_material_eval, the Voigt round trip and the Lame
 * constants per call: the operations of materials/svk.c (tf_svk_eval,
 * tf_green_lagrange) in their order, so the same bits as the svk law (the
 * unit tests compare the solver's forces with its energy, and a law
 * registered in a test with the same capabilities).  Returns -1 when
 * det F <= 0. */
static int hooke_stress(const tf_colloc *c, const double F[9], double S[9], double *W)
{
    if (!(tf_det3(F) > 0)) {
        return -1;
    }
    double H[9], E[9], lambda = c->lame_lambda, mu = c->lame_mu;
    for (int k = 0; k < 9; ++k) {
        H[k] = F[k] - (k % 4 == 0);
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = i; j < 3; ++j) {
            double hh = H[i] * H[j] + H[3 + i] * H[3 + j] + H[6 + i] * H[6 + j];
            E[3 * i + j] = E[3 * j + i] = 0.5 * (H[3 * i + j] + H[3 * j + i] + hh);
        }
    }
    double tr = E[0] + E[4] + E[8];
    for (int k = 0; k < 9; ++k) {
        S[k] = 2 * mu * E[k] + (k % 4 == 0 ? lambda * tr : 0);
    }
    if (W) {
        double ee = 0;
        for (int k = 0; k < 9; ++k) {
            ee += E[k] * E[k];
        }
        *W = 0.5 * lambda * tr * tr + mu * ee;
    }
    return 0;
}

/* First Piola-Kirchhoff stress P (and the energy density in *W) of particle
 * i at F; returns 0, or -1 when det F <= 0. */
static int stress(tf_colloc *c, size_t i, const double F[9], double dt, double P[9], double *W)
{
    double S6[6], S[9];
    if (c->hooke) {
        if (hooke_stress(c, F, S, W) != 0) {
            return -1;
        }
    } else if (tf_material_eval(&c->mat, F, dt, c->hold + i * c->hsize, c->hnew + i * c->hsize,
                                S6, NULL, W) != TF_MAT_OK) {
        return -1;
    } else {
        voigt_to_tensor(S6, S);
    }
    if (c->small) {
        for (int k = 0; k < 9; ++k) {
            P[k] = S[k];
        }
    } else {
        mul3(F, S, P);
    }
    if (c->opts.kv > 0) {
        double wv = volume_term(c->opts.kv, F, P);
        if (W) {
            *W += wv;
        }
    }
    return 0;
}

/* Phase 1 for particle i: F_i = I + G_i; then what particle i sends,
 * Q_i = v_i P_i A_i^-1 - beta_i G_i, and its own force Q_i s_i + beta_i q_i.
 * Returns 0, or -1 when det F_i <= 0. */
static int phase1(tf_colloc *c, size_t i, const double *u, double dt, int want_energy)
{
    const double *ainv = c->ainv + 9 * i;
    double G[9], q[3], F[9], P[9], M[9], W = 0;
    gradient(c, i, u, G, q);
    for (int k = 0; k < 9; ++k) {
        F[k] = G[k] + (k % 4 == 0 ? 1 : 0);
    }
    if (stress(c, i, F, dt, P, want_energy ? &W : NULL) != 0) {
        return -1;
    }
    double *out = c->ph1 + TF_COLLOC_PH1 * i, vi = c->vol[i], bi = c->beta[i];
    const double *s = c->s + 3 * i;
    for (int k = 0; k < 9; ++k) {
        P[k] *= vi;
    }
    mul3(P, ainv, M);
    for (int k = 0; k < 9; ++k) {
        out[k] = M[k] - bi * G[k];
    }
    for (int a = 0; a < 3; ++a) {
        out[9 + a] = out[3 * a] * s[0] + out[3 * a + 1] * s[1] + out[3 * a + 2] * s[2] + bi * q[a];
        out[12 + a] = u[3 * i + (size_t)a];
    }
    if (want_energy) {
        c->epart[i] = vi * W + residual_energy(c, i, u, G);
    }
    return 0;
}

/* Phase 2 for particle (or image) k: the forces of every support that
 * holds it, -Q_i y_ik + beta_i w_ik (u_i - u_k), after its own (an image
 * has no stress of its own). */
static void phase2(const tf_colloc *c, size_t k, const double *u, double *f)
{
    const double *uk = u + 3 * k;
    double b = c->bsum[k], f0 = -b * uk[0], f1 = -b * uk[1], f2 = -b * uk[2];
    if (k < c->n) {
        const double *own = c->ph1 + TF_COLLOC_PH1 * k + 9;
        f0 += own[0];
        f1 += own[1];
        f2 += own[2];
    }
    for (uint32_t e = c->rstart[k]; e < c->rstart[k + 1]; ++e) {
        size_t i = c->rsrc[e];
        const double *Q = c->ph1 + TF_COLLOC_PH1 * i, *y = c->ryc + 4 * (size_t)e, *ui = Q + 12;
        double ce = y[3];
        f0 += ce * ui[0] - (Q[0] * y[0] + Q[1] * y[1] + Q[2] * y[2]);
        f1 += ce * ui[1] - (Q[3] * y[0] + Q[4] * y[1] + Q[5] * y[2]);
        f2 += ce * ui[2] - (Q[6] * y[0] + Q[7] * y[1] + Q[8] * y[2]);
    }
    f[3 * k] = f0;
    f[3 * k + 1] = f1;
    f[3 * k + 2] = f2;
}

int tf_colloc_eval(tf_ctx *ctx, tf_colloc *c, const double *u, double dt, double *f, double *energy)
{
    size_t n = c->n, na = c->na;
    int want = energy != NULL, failed = 0;
    double *fa = f;
    if (na > n) { /* the images' displacements, and forces on them too */
        tf_colloc_ghost_fill(c, u, c->ue);
        u = c->ue;
        fa = c->fe;
    }
#pragma omp parallel num_threads(tf_colloc_threads(c))
    {
#pragma omp for schedule(static) reduction(| : failed)
        for (size_t i = 0; i < n; ++i) {
            c->bad[i] = phase1(c, i, u, dt, want) != 0;
            failed |= c->bad[i];
        }
        if (!failed) {
#pragma omp for schedule(static)
            for (size_t k = 0; k < na; ++k) {
                phase2(c, k, u, fa);
            }
        }
    }
    if (failed) {
        size_t i = 0;
        while (!c->bad[i]) {
            ++i;
        }
        return tf_fail(ctx,
                       "particle %zu at (%g, %g, %g) mm inverted (det F <= 0): the motion is not "
                       "physical here (step too large, or a load beyond the material)",
                       i, c->X[3 * i], c->X[3 * i + 1], c->X[3 * i + 2]);
    }
    if (na > n) {
        tf_colloc_ghost_fold(c, fa, f);
    }
    if (want) {
        double e = 0;
        for (size_t i = 0; i < n; ++i) {
            e += c->epart[i];
        }
        *energy = e;
    }
    return 0;
}

void tf_colloc_deformation(tf_colloc *c, const double *u, double *F)
{
    if (c->na > c->n) {
        tf_colloc_ghost_fill(c, u, c->ue);
        u = c->ue;
    }
#pragma omp parallel for schedule(static) num_threads(tf_colloc_threads(c))
    for (size_t i = 0; i < c->n; ++i) {
        double q[3], *Fi = F + 9 * i;
        gradient(c, i, u, Fi, q);
        Fi[0] += 1;
        Fi[4] += 1;
        Fi[8] += 1;
    }
}

int tf_colloc_forces(tf_ctx *ctx, tf_colloc *c, const double *u, double dt, double *f,
                     double *energy)
{
    return tf_colloc_eval(ctx, c, u, dt, f, energy);
}

/* The nearest particle to x (the lowest index of equally near ones). */
static size_t nearest(const tf_colloc *c, const double x[3])
{
    size_t best = 0;
    double best_r2 = INFINITY;
    for (size_t i = 0; i < c->n; ++i) {
        const double *xi = c->X + 3 * i;
        const double d0 = x[0] - xi[0], d1 = x[1] - xi[1], d2 = x[2] - xi[2];
        const double r2 = d0 * d0 + d1 * d1 + d2 * d2;
        if (r2 < best_r2) {
            best_r2 = r2;
            best = i;
        }
    }
    return best;
}

int tf_colloc_field(tf_ctx *ctx, const tf_colloc *c, const double *u, const double *x, size_t np,
                    double *uh, double *grad)
{
    double *ue = NULL;
    if (c->na > c->n) { /* the images' displacements, in a buffer of this call's own */
        ue = malloc(3 * c->na * sizeof *ue);
        if (ue == NULL) {
            return tf_fail(ctx, "out of memory for the collocation field");
        }
        tf_colloc_ghost_fill(c, u, ue);
        u = ue;
    }
    for (size_t j = 0; j < np; ++j) {
        const double *xj = x + 3 * j;
        const size_t i = nearest(c, xj);
        const double *xi = c->X + 3 * i, *ui = u + 3 * i;
        const double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
        double G[9], q[3];
        gradient(c, i, u, G, q);
        for (int a = 0; a < 3; ++a) {
            uh[3 * j + (size_t)a] = ui[a] + G[3 * a] * d[0] + G[3 * a + 1] * d[1] + G[3 * a + 2] * d[2];
        }
        if (grad != NULL) {
            memcpy(grad + 9 * j, G, sizeof G);
        }
    }
    free(ue);
    return 0;
}
