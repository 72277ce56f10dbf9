/*
 * constraints.h — essential boundary conditions of a Galerkin system, shared
 * by the Galerkin solvers: which DOFs a fixed region prescribes and to what
 * value, and the stiffness they leave to factorise, either K restricted to
 * the free DOFs (direct elimination) or K with the seed's penalty (eq 28).
 */
#ifndef TF_CONSTRAINTS_H
#define TF_CONSTRAINTS_H

#include <stddef.h>

#include "numerics/csc.h"
#include "problem/problem.h"

typedef struct tf_constraints {
    size_t n3;            /* 3N DOFs */
    unsigned char *fixed; /* 3N: prescribed DOF */
    double *ubar;         /* 3N: prescribed values (0 at free DOFs), mm */
    int *free_index;      /* 3N: position among the free DOFs, or -1 */
    size_t n_free;
} tf_constraints;

/* The prescribed DOFs and values of a problem (exact: its analytic
 * solution).  Returns 0, or -1 when out of memory. */
int tf_constraints_init(tf_constraints *c, const tf_problem *p);
void tf_constraints_release(tf_constraints *c);

/* K restricted to the free DOFs, in free-DOF numbering.  0, or -1 (memory). */
int tf_constraints_reduce(const tf_constraints *c, const tf_csc *k, tf_csc *kf);

/* Seed eq 28: the diagonal block of a fixed node (its prescribed
 * components) multiplied by lambda in a copy kp of K; rhs (3N, holding the
 * loads) gets lambda K_jj u_bar_j at the fixed DOFs.  0, or -1 (memory). */
int tf_constraints_penalise(const tf_constraints *c, const tf_csc *k, double lambda, tf_csc *kp,
                            double *rhs);

#endif /* TF_CONSTRAINTS_H */
