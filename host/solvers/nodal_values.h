/*
 * nodal_values.h — between EFG's nodal parameters and displacements at the
 * nodes.  MLS shape functions do not interpolate: the unknowns d_J are
 * parameters, and the displacement at node I is u(x_I) = sum_J phi_J(x_I) d_J
 * (Lambda d, Lambda_IJ = phi_J(x_I), one sparse N x N matrix applied to
 * each component).  Outputs, reactions and starting values go through it;
 * its inverse (an LU factorisation by UMFPACK, SuiteSparse) turns given
 * nodal displacements back into parameters.
 */
#ifndef TF_NODAL_VALUES_H
#define TF_NODAL_VALUES_H

#include <stddef.h>

#include "base/context.h"
#include "meshfree/shape.h"

typedef struct tf_nodal_map {
    size_t n;        /* nodes */
    size_t *ptr;     /* row I: entries ptr[I] .. ptr[I+1] */
    int *col;        /* node J */
    double *val;     /* phi_J(x_I) */
    void *symbolic, *numeric; /* UMFPACK's factorisation of Lambda (lazily) */
    double *u_cache, *d_cache; /* the last u turned into parameters, and them */
    int cache_ok;
} tf_nodal_map;

/* Lambda of the shape functions sh at their own nodes.  Returns 0, or -1
 * with a message. */
int tf_nodal_map_build(tf_ctx *ctx, tf_nodal_map *m, const tf_shape *sh);
void tf_nodal_map_free(tf_nodal_map *m);

/* u = Lambda d for ncol columns of 3N (u and d distinct). */
void tf_nodal_map_values(const tf_nodal_map *m, const double *d, double *u, size_t ncol);

/* d = Lambda^-1 u (one column of 3N).  Returns 0, or -1 with a message
 * (Lambda singular, out of memory).  Not reentrant: the first call
 * factorises. */
int tf_nodal_map_params(tf_ctx *ctx, tf_nodal_map *m, const double *u, double *d);

/* The parameters of u through a one-entry cache: the same u asked again
 * (the field of one solution at many points, from many threads at once)
 * costs a comparison.  Thread-safe; the pointer stays valid until a
 * different u is asked for.  Returns NULL with a message in ctx->err. */
const double *tf_nodal_map_params_of(tf_ctx *ctx, tf_nodal_map *m, const double *u);

#endif /* TF_NODAL_VALUES_H */
