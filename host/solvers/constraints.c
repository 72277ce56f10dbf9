/*
 * constraints.c — essential boundary conditions (constraints.h).
 */
#include "solvers/constraints.h"

#include <stdlib.h>
#include <string.h>

#include "problem/analytic.h"

int tf_constraints_init(tf_constraints *c, const tf_problem *p)
{
    memset(c, 0, sizeof *c);
    c->n3 = 3 * p->cloud.n;
    c->fixed = calloc(c->n3 + 1, 1);
    c->ubar = calloc(c->n3 + 1, sizeof *c->ubar);
    c->free_index = malloc((c->n3 + 1) * sizeof *c->free_index);
    if (!c->fixed || !c->ubar || !c->free_index) {
        tf_constraints_release(c);
        return -1;
    }
    for (size_t r = 0; r < p->n_fixed; ++r) {
        const tf_fixed *fx = &p->fixed[r];
        for (size_t q = 0; q < fx->n_nodes; ++q) {
            size_t i = fx->nodes[q];
            double u[3], g[9];
            if (fx->exact) {
                tf_analytic_eval(p, p->cloud.xyz + 3 * i, u, g);
            }
            for (int a = 0; a < 3; ++a) {
                if (fx->components & (1u << a)) {
                    c->fixed[3 * i + (size_t)a] = 1;
                    c->ubar[3 * i + (size_t)a] = fx->exact ? u[a] : fx->value[a];
                }
            }
        }
    }
    for (size_t d = 0; d < c->n3; ++d) {
        c->free_index[d] = c->fixed[d] ? -1 : (int)c->n_free++;
    }
    return 0;
}

void tf_constraints_release(tf_constraints *c)
{
    free(c->fixed);
    free(c->ubar);
    free(c->free_index);
    memset(c, 0, sizeof *c);
}

int tf_constraints_reduce(const tf_constraints *c, const tf_csc *k, tf_csc *kf)
{
    size_t nnz = 0;
    for (size_t j = 0; j < k->n; ++j) {
        for (int q = k->p[j]; q < k->p[j + 1] && !c->fixed[j]; ++q) {
            nnz += !c->fixed[k->i[q]];
        }
    }
    kf->n = c->n_free;
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
        if (c->fixed[j]) {
            continue;
        }
        kf->p[c->free_index[j]] = (int)q2;
        for (int q = k->p[j]; q < k->p[j + 1]; ++q) {
            if (!c->fixed[k->i[q]]) {
                kf->i[q2] = c->free_index[k->i[q]];
                kf->x[q2++] = k->x[q];
            }
        }
    }
    kf->p[kf->n] = (int)q2;
    return 0;
}

int tf_constraints_penalise(const tf_constraints *c, const tf_csc *k, double lambda, tf_csc *kp,
                            double *rhs)
{
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
        if (c->fixed[d]) {
            rhs[d] = 0;
        }
    }
    for (size_t j = 0; j < k->n; ++j) {
        for (int q = k->p[j]; q < k->p[j + 1] && c->fixed[j]; ++q) {
            size_t i = (size_t)k->i[q];
            if (i / 3 == j / 3 && c->fixed[i]) {
                kp->x[q] *= lambda;
                rhs[i] += kp->x[q] * c->ubar[j];
                if (i != j) {
                    rhs[j] += kp->x[q] * c->ubar[i];
                }
            }
        }
    }
    return 0;
}
