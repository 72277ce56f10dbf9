/*
 * nl_patch.c — the patch tangent (nl_internal.h; docs/solver.md).
 *
 * Under a contact force the nonlinearity is local: on block48's 3 N
 * neo-Hookean case 50-80 % of the squared residual sits on the 1 % of DOFs
 * under the contact patch (docs/validation.md §13).  The DOFs A of the
 * nodes within the patch radius of a contact site are ordered last in the
 * factor (cholmod_solve.h: tf_chol_analyse_last), so that with
 * K0 = [K_BB K_BA; K_AB K_AA] and its factor L0 = [L_BB 0; L_AB L_AA0],
 * L_AA0 L_AA0^T = K_AA - K_AB K_BB^-1 K_BA (the Schur complement of the
 * rest onto A).  A matrix that differs from K0 only in the AA block,
 * K0 + P dK P^T, has the Schur complement S0 + dK with S0 = L_AA0 L_AA0^T,
 * and so the factor L0 with L_AA0 replaced by chol(S0 + dK): an m x m dense
 * Cholesky (LAPACK dpotrf), no refactorisation (the block form of
 * Cholesky's method, e.g. Golub & Van Loan, Matrix Computations, 4th ed.,
 * §4.2.9).  Each Newton iteration takes dK from the tangent on the cells
 * whose supports lie in A, now and at the base (choose below); BFGS's
 * pairs on top learn the far field.
 */
#include <cblas.h>
#include <lapacke.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "meshfree/quadrature.h"
#include "solvers/nonlinear/nl_internal.h"

void nl_patch_free(nl_patch *p)
{
    free(p->dof);
    free(p->cell);
    free(p->list);
    free(p->pos);
    free(p->s0);
    free(p->k0);
    free(p->w);
    memset(p, 0, sizeof *p);
}

/* The patch's cells: those whose centre lies within the radius of a
 * contact site; A: the nodes of their supports.  The block update then is
 * the tangent of a body whose patch cells are in the current state and the
 * others in the base state: a sum of cell tangents, as a true tangent is
 * (with A the nodes near the site and the tangent of every cell touching
 * them, S0 + K_t,AA - K0,AA mixed K_t's diagonal blocks with K0's
 * couplings and lost definiteness in 4 of 10 updates at 21 x 21 x 5; this
 * form in 0 to 2 of 20 to 40, iterates far from equilibrium).  The radius is that of the cells: A reaches a
 * support radius further, so |A| follows the node density (and the
 * support) as well as the radius. */
static size_t choose(nl_solver *s, double radius)
{
    const tf_problem *pb = s->base.problem;
    nl_patch *p = &s->patch;
    memset(p->dof, 0, 3 * pb->cloud.n * sizeof *p->dof);
    for (size_t c = 0; c < s->ncell; ++c) {
        double x[3], half[3];
        tf_cells_box(&s->sh.cells, c, x, half);
        p->cell[c] = 0;
        for (size_t k = 0; k < pb->n_contacts && !p->cell[c]; ++k) {
            const double *a = pb->contacts[k].at;
            double r2 = 0;
            for (int i = 0; i < 3; ++i) {
                r2 += (x[i] - a[i]) * (x[i] - a[i]);
            }
            p->cell[c] = r2 <= radius * radius;
        }
        for (size_t q = s->cs.ptr[c]; q < s->cs.ptr[c + 1] && p->cell[c]; ++q) {
            for (size_t a = 3 * (size_t)s->cs.nodes[q], e = a + 3; a < e; ++a) {
                p->dof[a] = !s->bc.fixed[a]; /* (a fixed DOF is alone in the factor: nl_model.c) */
            }
        }
    }
    size_t m = 0;
    for (size_t i = 0; i < 3 * pb->cloud.n; ++i) {
        m += p->dof[i];
    }
    return m;
}

int nl_patch_init(nl_solver *s)
{
    nl_patch *p = &s->patch;
    const tf_newton_opts *o = &s->base.opts.newton;
    size_t n3 = 3 * s->sh.cloud->n;
    memset(p, 0, sizeof *p);
    if (o->tangent != TF_TANGENT_PATCH || s->weak || s->relaxes || s->unsym ||
        s->base.problem->n_contacts == 0) {
        return 0; /* BFGS */
    }
    p->dof = malloc(n3 * sizeof *p->dof);
    p->cell = malloc(s->ncell * sizeof *p->cell);
    p->pos = malloc(n3 * sizeof *p->pos);
    if (!p->dof || !p->cell || !p->pos) {
        return tf_fail(s->base.ctx, "out of memory");
    }
    p->m = choose(s, o->patch_radius);
    if (p->m == 0 || p->m == n3) {
        nl_patch_free(p);
        return 0;
    }
    size_t mm = p->m * p->m;
    p->list = malloc(p->m * sizeof *p->list);
    p->s0 = malloc(mm * sizeof *p->s0);
    p->k0 = malloc(mm * sizeof *p->k0);
    p->w = malloc(mm * sizeof *p->w);
    if (!p->list || !p->s0 || !p->k0 || !p->w) {
        return tf_fail(s->base.ctx, "out of memory");
    }
    p->on = 1;
    return 0;
}

/* The tangent's AA block (A holds no fixed DOF) into a, lower triangle,
 * A's order. */
static void block_of_k(const nl_solver *s, double *a)
{
    const nl_patch *p = &s->patch;
    const tf_csc *k = &s->k;
    size_t m = p->m;
    memset(a, 0, m * m * sizeof *a);
    for (size_t jj = 0; jj < m; ++jj) {
        size_t j = p->list[jj];
        for (int q = k->p[j]; q < k->p[j + 1]; ++q) {
            size_t i = (size_t)k->i[q];
            int ii = p->pos[i];
            if (ii < 0) {
                continue;
            }
            size_t r = (size_t)ii > jj ? (size_t)ii : jj, c = (size_t)ii > jj ? jj : (size_t)ii;
            a[r + m * c] = k->x[q];
        }
    }
}

int nl_patch_base(nl_solver *s)
{
    nl_patch *p = &s->patch;
    p->base = 0;
    p->want_k0 = 0;
    if (!p->on) {
        return 0;
    }
    size_t m = p->m, n3 = s->k.n, ld;
    const int *perm;
    double *l = tf_chol_trailing(s->chol, m, &ld, &perm);
    for (size_t i = 0; l != NULL && i < m; ++i) {
        l = p->dof[perm[n3 - m + i]] ? l : NULL; /* A is last */
    }
    if (l == NULL) { /* CHOLMOD did not keep A last: BFGS from here on */
        p->fallbacks++;
        p->on = 0;
        return 0;
    }
    double t0 = omp_get_wtime();
    for (size_t i = 0; i < n3; ++i) {
        p->pos[i] = -1;
    }
    for (size_t i = 0; i < m; ++i) {
        p->list[i] = (uint32_t)perm[n3 - m + i];
        p->pos[p->list[i]] = (int)i;
    }
    for (size_t j = 0; j < m; ++j) { /* L_AA0, its upper triangle zero */
        for (size_t i = 0; i < m; ++i) {
            p->w[i + m * j] = i >= j ? l[i + ld * j] : 0;
        }
    }
    cblas_dsyrk(CblasColMajor, CblasLower, CblasNoTrans, (int)m, (int)m, 1.0, p->w, (int)m,
                0.0, p->s0, (int)m);
    p->want_k0 = 1;
    s->st.t_patch += omp_get_wtime() - t0;
    return 0;
}

int nl_patch_k0(nl_solver *s, const double *d, double dt, nl_fault *fault)
{
    nl_patch *p = &s->patch;
    p->want_k0 = 0;
    int rc = nl_assemble_patch(s, d, dt, fault);
    if (rc == 0) {
        block_of_k(s, p->k0);
        p->base = 1;
    }
    return rc;
}

int nl_patch_update(nl_solver *s)
{
    nl_patch *p = &s->patch;
    size_t m = p->m, ld;
    const int *perm;
    double t0 = omp_get_wtime();
    double *l = tf_chol_trailing(s->chol, m, &ld, &perm);
    if (!p->base || l == NULL) {
        return 1;
    }
    block_of_k(s, p->w); /* K_t,AA */
    for (size_t j = 0; j < m; ++j) {
        for (size_t i = j; i < m; ++i) {
            p->w[i + m * j] += p->s0[i + m * j] - p->k0[i + m * j];
        }
    }
    int info = LAPACKE_dpotrf(LAPACK_COL_MAJOR, 'L', (lapack_int)m, p->w, (lapack_int)m);
    s->st.patches++;
    if (info != 0) {
        s->st.patch_kept++;
        s->st.t_patch += omp_get_wtime() - t0;
        return 1;
    }
    for (size_t j = 0; j < m; ++j) {
        memcpy(l + ld * j + j, p->w + m * j + j, (m - j) * sizeof *l);
    }
    s->st.t_patch += omp_get_wtime() - t0;
    return 0;
}
