/*
 * solver.c — build once, solve many (solver.h).
 */
#include "solvers/solver.h"

#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solvers/assemble.h"
#include "solvers/cholmod_solve.h"
#include "solvers/loads.h"
#include "base/log.h"
#include "verify/reference.h"

struct tf_solver {
    const tf_scene *sc;
    tf_shape sh;
    int shape_ok;
    tf_csc k;          /* full stiffness, every DOF */
    unsigned char *fixed; /* 3N: prescribed DOF */
    double *ubar;      /* 3N: prescribed values (0 at free DOFs) */
    int *free_index;   /* 3N: position among the free DOFs, or -1 */
    size_t n_free;
    double *f0;        /* 3N: scene loads */
    double *basis;     /* n_contacts x (3N x 3): unit forces at each site */
    double *rhs0;      /* system size: constant part of every right-hand side */
    tf_chol *chol;
    tf_solver_info info;
};

static int fail_oom(char *err, size_t errlen)
{
    snprintf(err, errlen, "out of memory");
    return -1;
}

/* Prescribed DOFs and their values (exact: the reference solution). */
static void essential(tf_solver *s)
{
    const tf_scene *sc = s->sc;
    for (size_t r = 0; r < sc->n_fixed; ++r) {
        const tf_fixed *fx = &sc->fixed[r];
        for (size_t q = 0; q < fx->n_nodes; ++q) {
            size_t i = fx->nodes[q];
            double u[3], g[9];
            if (fx->exact) {
                tf_reference_eval(sc, sc->cloud.xyz + 3 * i, u, g);
            }
            for (int a = 0; a < 3; ++a) {
                if (fx->components & (1u << a)) {
                    s->fixed[3 * i + (size_t)a] = 1;
                    s->ubar[3 * i + (size_t)a] = fx->exact ? u[a] : fx->value[a];
                }
            }
        }
    }
    s->n_free = 0;
    for (size_t d = 0; d < s->k.n; ++d) {
        s->free_index[d] = s->fixed[d] ? -1 : (int)s->n_free++;
    }
}

static int build_loads(tf_solver *s, char *err, size_t errlen)
{
    const tf_scene *sc = s->sc;
    size_t n3 = s->k.n;
    for (size_t k = 0; k < sc->n_loads; ++k) {
        const tf_load *ld = &sc->loads[k];
        int rc = ld->exact ? tf_load_exact(&s->sh, sc, &ld->patch, s->f0, err, errlen)
                           : tf_load_patch(&s->sh, sc, &ld->patch, ld->force, s->f0, err, errlen);
        if (rc != 0) {
            return -1;
        }
    }
    for (size_t c = 0; c < sc->n_contacts; ++c) {
        if (tf_load_patch(&s->sh, sc, &sc->contacts[c].patch, NULL, s->basis + 3 * n3 * c, err,
                          errlen) != 0) {
            return -1;
        }
    }
    return 0;
}

/* K restricted to the free DOFs (direct elimination). */
static int free_block(const tf_solver *s, tf_csc *kf)
{
    const tf_csc *k = &s->k;
    size_t nnz = 0;
    for (size_t j = 0; j < k->n; ++j) {
        for (int q = k->p[j]; q < k->p[j + 1] && !s->fixed[j]; ++q) {
            nnz += !s->fixed[k->i[q]];
        }
    }
    kf->n = s->n_free;
    kf->nnz = nnz;
    kf->p = malloc((kf->n + 1) * sizeof *kf->p);
    kf->i = malloc((nnz + 1) * sizeof *kf->i);
    kf->x = malloc((nnz + 1) * sizeof *kf->x);
    if (!kf->p || !kf->i || !kf->x) {
        tf_csc_free(kf);
        return -1;
    }
    size_t q2 = 0;
    for (size_t j = 0; j < k->n; ++j) {
        if (s->fixed[j]) {
            continue;
        }
        kf->p[s->free_index[j]] = (int)q2;
        for (int q = k->p[j]; q < k->p[j + 1]; ++q) {
            if (!s->fixed[k->i[q]]) {
                kf->i[q2] = s->free_index[k->i[q]];
                kf->x[q2++] = k->x[q];
            }
        }
    }
    kf->p[kf->n] = (int)q2;
    return 0;
}

/* Seed eq 28: the diagonal block of a fixed node (its prescribed
 * components) is multiplied by lambda, and its right-hand side becomes
 * lambda K_jj u_bar_j. */
static int penalised(const tf_solver *s, tf_csc *kp, double *rhs)
{
    const tf_csc *k = &s->k;
    double lambda = s->sc->solver.penalty;
    kp->n = k->n;
    kp->nnz = k->nnz;
    kp->p = malloc((k->n + 1) * sizeof *kp->p);
    kp->i = malloc(k->nnz * sizeof *kp->i);
    kp->x = malloc(k->nnz * sizeof *kp->x);
    if (!kp->p || !kp->i || !kp->x) {
        tf_csc_free(kp);
        return -1;
    }
    memcpy(kp->p, k->p, (k->n + 1) * sizeof *kp->p);
    memcpy(kp->i, k->i, k->nnz * sizeof *kp->i);
    memcpy(kp->x, k->x, k->nnz * sizeof *kp->x);
    for (size_t d = 0; d < k->n; ++d) {
        if (s->fixed[d]) {
            rhs[d] = 0;
        }
    }
    for (size_t j = 0; j < k->n; ++j) {
        for (int q = k->p[j]; q < k->p[j + 1] && s->fixed[j]; ++q) {
            size_t i = (size_t)k->i[q];
            if (i / 3 == j / 3 && s->fixed[i]) {
                kp->x[q] *= lambda;
                rhs[i] += kp->x[q] * s->ubar[j];
                if (i != j) {
                    rhs[j] += kp->x[q] * s->ubar[i];
                }
            }
        }
    }
    return 0;
}

/* The system matrix and the constant part of every right-hand side, then
 * the factorisation. */
static int factorise(tf_solver *s, char *err, size_t errlen)
{
    size_t n3 = s->k.n;
    tf_csc a = {0};
    tf_chol_info ci;
    if (s->sc->solver.bc == TF_BC_PENALTY) {
        s->rhs0 = malloc(n3 * sizeof *s->rhs0);
        if (s->rhs0 == NULL) {
            return fail_oom(err, errlen);
        }
        memcpy(s->rhs0, s->f0, n3 * sizeof *s->rhs0);
        if (penalised(s, &a, s->rhs0) != 0) {
            return fail_oom(err, errlen);
        }
    } else {
        double *ku = malloc(n3 * sizeof *ku);
        s->rhs0 = malloc((s->n_free + 1) * sizeof *s->rhs0);
        if (ku == NULL || s->rhs0 == NULL || free_block(s, &a) != 0) {
            free(ku);
            return fail_oom(err, errlen);
        }
        /* F_f - K_fc u_bar_c */
        tf_csc_symv(&s->k, s->ubar, ku, 1);
        for (size_t d = 0; d < n3; ++d) {
            if (!s->fixed[d]) {
                s->rhs0[s->free_index[d]] = s->f0[d] - ku[d];
            }
        }
        free(ku);
    }
    if (a.n == 0) {
        tf_csc_free(&a);
        snprintf(err, errlen, "every degree of freedom is fixed: nothing to solve");
        return -1;
    }
    s->chol = tf_chol_factor(&a, &ci, err, errlen);
    tf_csc_free(&a);
    if (s->chol == NULL) {
        return -1;
    }
    s->info.t_factor = ci.t_analyse + ci.t_factor;
    s->info.nnz_l = ci.nnz_l;
    s->info.flops = ci.flops;
    s->info.ordering = ci.ordering;
    return 0;
}

static int allocate(tf_solver *s)
{
    size_t n3 = 3 * s->sc->cloud.n;
    s->fixed = calloc(n3, 1);
    s->ubar = calloc(n3, sizeof *s->ubar);
    s->free_index = malloc(n3 * sizeof *s->free_index);
    s->f0 = calloc(n3, sizeof *s->f0);
    s->basis = calloc(3 * n3 * (s->sc->n_contacts + 1), sizeof *s->basis);
    return s->fixed && s->ubar && s->free_index && s->f0 && s->basis ? 0 : -1;
}

static void announce(const tf_solver *s)
{
    const tf_scene *sc = s->sc;
    const tf_cells *c = &s->sh.cells;
    tf_info("solver: %zu nodes, %zu DOFs, %zu cells x %u^3 Gauss points, support %g x spacing "
            "(%s-centred), %s, volumetric strain %s, BCs by %s",
            sc->cloud.n, 3 * sc->cloud.n, tf_cells_count(c), c->gauss, sc->solver.support,
            sc->solver.centre == TF_SUPPORT_CELL ? "cell" : "point",
            sc->solver.polynomial ? "RBF + linear polynomial" : "RBF only",
            sc->solver.volumetric == TF_VOLUMETRIC_CELL ? "averaged per cell" : "at every point",
            sc->solver.bc == TF_BC_PENALTY ? "penalty" : "elimination");
}

tf_solver *tf_solver_new(const tf_scene *scene, char *err, size_t errlen)
{
    tf_solver *s = calloc(1, sizeof *s);
    if (s == NULL) {
        fail_oom(err, errlen);
        return NULL;
    }
    s->sc = scene;
    tf_shape_stats_reset(&s->info.st);
    if (tf_shape_init(&s->sh, scene) != 0) {
        fail_oom(err, errlen);
        tf_solver_free(s);
        return NULL;
    }
    s->shape_ok = 1;
    announce(s);
    tf_assembly_info ai;
    tf_lame l = tf_lame_from(scene->young, scene->poisson);
    if (tf_assemble_stiffness(&s->sh, &l, scene->solver.volumetric == TF_VOLUMETRIC_CELL, &s->k,
                              &ai, err, errlen) != 0) {
        tf_solver_free(s);
        return NULL;
    }
    s->info.nodes = scene->cloud.n;
    s->info.dofs = s->k.n;
    s->info.points = ai.points;
    s->info.nnz_k = s->k.nnz;
    s->info.t_pattern = ai.t_pattern;
    s->info.t_shape = ai.t_values * ai.shape_fraction;
    s->info.t_assemble = ai.t_values - s->info.t_shape;
    s->info.st = ai.st;
    tf_info("solver: assembled %zu Gauss points in %.2f s (K has %zu stored entries)", ai.points,
            ai.t_pattern + ai.t_values, s->k.nnz);
    double t0 = omp_get_wtime();
    if (allocate(s) != 0) {
        fail_oom(err, errlen);
        tf_solver_free(s);
        return NULL;
    }
    essential(s);
    if (build_loads(s, err, errlen) != 0) {
        tf_solver_free(s);
        return NULL;
    }
    s->info.free_dofs = s->n_free;
    s->info.t_loads = omp_get_wtime() - t0;
    tf_info("solver: factorising %zu unknowns (CHOLMOD)",
            scene->solver.bc == TF_BC_PENALTY ? s->k.n : s->n_free);
    if (factorise(s, err, errlen) != 0) {
        tf_solver_free(s);
        return NULL;
    }
    tf_info("solver: factorised in %.2f s (%s ordering, %.3g entries in L)", s->info.t_factor,
            s->info.ordering, s->info.nnz_l);
    return s;
}

void tf_solver_free(tf_solver *s)
{
    if (s == NULL) {
        return;
    }
    if (s->shape_ok) {
        tf_shape_free(&s->sh);
    }
    tf_csc_free(&s->k);
    free(s->fixed);
    free(s->ubar);
    free(s->free_index);
    free(s->f0);
    free(s->basis);
    free(s->rhs0);
    tf_chol_free(s->chol);
    free(s);
}

const tf_solver_info *tf_solver_info_of(const tf_solver *s) { return &s->info; }
size_t tf_solver_node_count(const tf_solver *s) { return s->sc->cloud.n; }
const double *tf_solver_coords(const tf_solver *s) { return s->sc->cloud.xyz; }
uint32_t tf_solver_node_number(const tf_solver *s, size_t index)
{
    (void)s;
    return (uint32_t)index + 1;
}
int tf_solver_dof_fixed(const tf_solver *s, size_t dof) { return s->fixed[dof]; }
const tf_shape *tf_solver_shape(const tf_solver *s) { return &s->sh; }

/* Full load vector of one case: scene loads + basis force. */
static void load_vector(const tf_solver *s, int contact, const double *force, double *f)
{
    size_t n3 = s->k.n;
    memcpy(f, s->f0, n3 * sizeof *f);
    if (contact >= 0) {
        const double *b = s->basis + 3 * n3 * (size_t)contact;
        for (size_t d = 0; d < n3; ++d) {
            f[d] += b[d] * force[0] + b[n3 + d] * force[1] + b[2 * n3 + d] * force[2];
        }
    }
}

/* Right-hand side of one case in the factorised system's DOFs. */
static void rhs_of(const tf_solver *s, int contact, const double *force, double *f, double *rhs)
{
    size_t n3 = s->k.n;
    load_vector(s, contact, force, f);
    if (s->sc->solver.bc == TF_BC_PENALTY) {
        for (size_t d = 0; d < n3; ++d) {
            rhs[d] = s->fixed[d] ? s->rhs0[d] : f[d];
        }
    } else {
        for (size_t d = 0; d < n3; ++d) {
            if (!s->fixed[d]) {
                rhs[s->free_index[d]] = s->rhs0[s->free_index[d]] + f[d] - s->f0[d];
            }
        }
    }
}

int tf_solver_solve(tf_solver *s, int contact, const double *forces, size_t n, double *u,
                    char *err, size_t errlen)
{
    if (contact < -1 || contact >= (int)s->sc->n_contacts || (contact >= 0 && forces == NULL)) {
        snprintf(err, errlen, "no contact site %d in scene %s", contact, s->sc->name);
        return -1;
    }
    size_t n3 = s->k.n, m = s->sc->solver.bc == TF_BC_PENALTY ? n3 : s->n_free;
    double *b = malloc(m * n * sizeof *b), *x = malloc(m * n * sizeof *x);
    double *f = malloc(n3 * sizeof *f);
    if (!b || !x || !f) {
        free(b);
        free(x);
        free(f);
        return fail_oom(err, errlen);
    }
    double t0 = omp_get_wtime();
    for (size_t k = 0; k < n; ++k) {
        rhs_of(s, contact, contact >= 0 ? forces + 3 * k : NULL, f, b + k * m);
    }
    int rc = tf_chol_solve(s->chol, b, x, n, err, errlen);
    for (size_t k = 0; k < n && rc == 0; ++k) {
        double *uk = u + k * n3;
        for (size_t d = 0; d < n3; ++d) {
            uk[d] = m == n3 ? x[k * m + d]
                    : s->fixed[d] ? s->ubar[d]
                                  : x[k * m + (size_t)s->free_index[d]];
        }
    }
    s->info.t_solve += omp_get_wtime() - t0;
    s->info.solves += n;
    free(b);
    free(x);
    free(f);
    return rc;
}

int tf_solver_reactions(const tf_solver *s, int contact, const double force[3], const double *u,
                        double *r)
{
    if (contact < -1 || contact >= (int)s->sc->n_contacts) {
        return -1;
    }
    size_t n3 = s->k.n;
    double *f = malloc(n3 * sizeof *f);
    if (f == NULL) {
        return -1;
    }
    load_vector(s, contact, force, f);
    tf_csc_symv(&s->k, u, r, 1);
    for (size_t d = 0; d < n3; ++d) {
        r[d] -= f[d];
    }
    free(f);
    return 0;
}
