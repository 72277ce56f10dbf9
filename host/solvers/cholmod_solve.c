/*
 * cholmod_solve.c — CHOLMOD factorisation and solves (cholmod_solve.h).
 */
#include "solvers/cholmod_solve.h"

#include <cblas.h>
#include <cholmod.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* OpenBLAS splits its level-3 work by its thread count, and the factor's
 * bits follow the split: a fixed count keeps the result independent of
 * OMP_NUM_THREADS (which OpenBLAS would otherwise follow).  One thread, the
 * same as the tool pins for all of OpenBLAS (blas_pin.c), so the bits do not
 * depend on the machine's core count either; on 41x41x9 the factorisation
 * took 11.6 s with one thread and 12.0 s with two (pinned Haswell kernels). */
#define TF_BLAS_THREADS 1

struct tf_chol {
    cholmod_common cm;
    cholmod_factor *l;
    size_t n;
};

static const char *ordering_name(int ord)
{
    switch (ord) {
    case CHOLMOD_NATURAL:
        return "natural";
    case CHOLMOD_AMD:
        return "AMD";
    case CHOLMOD_METIS:
        return "METIS";
    case CHOLMOD_NESDIS:
        return "NESDIS";
    case CHOLMOD_COLAMD:
        return "COLAMD";
    case CHOLMOD_GIVEN:
        return "given";
    default:
        return "other";
    }
}

/* A cholmod_sparse header over our arrays (no copy). */
static cholmod_sparse wrap(const tf_csc *a)
{
    cholmod_sparse s;
    memset(&s, 0, sizeof s);
    s.nrow = s.ncol = a->n;
    s.nzmax = a->nnz;
    s.p = a->p;
    s.i = a->i;
    s.x = a->x;
    s.stype = -1;
    s.itype = CHOLMOD_INT;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
}

double tf_chol_rcond(tf_chol *c) { return cholmod_rcond(c->l, &c->cm); }

int tf_chol_solve(tf_ctx *ctx, tf_chol *c, const double *b, double *x, size_t ncol)
{
    cholmod_dense d;
    memset(&d, 0, sizeof d);
    openblas_set_num_threads(TF_BLAS_THREADS);
    d.nrow = c->n;
    d.ncol = ncol;
    d.nzmax = c->n * ncol;
    d.d = c->n;
    d.x = (void *)b;
    d.xtype = CHOLMOD_REAL;
    d.dtype = CHOLMOD_DOUBLE;
    cholmod_dense *r = cholmod_solve(CHOLMOD_A, c->l, &d, &c->cm);
    if (r == NULL) {
        return tf_fail(ctx, "CHOLMOD solve failed (status %d)", c->cm.status);
    }
    memcpy(x, r->x, c->n * ncol * sizeof *x);
    cholmod_free_dense(&r, &c->cm);
    return 0;
}

/* A handle for n unknowns with CHOLMOD started, quiet; NULL with a message. */
static tf_chol *chol_new(tf_ctx *ctx, size_t n)
{
    tf_chol *c = calloc(1, sizeof *c);
    if (c == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    cholmod_start(&c->cm);
    c->cm.print = 0;
    c->n = n;
    return c;
}

static int cholmod_ordering(tf_ordering ord)
{
    return ord == TF_ORDER_AMD      ? CHOLMOD_AMD
           : ord == TF_ORDER_NESDIS ? CHOLMOD_NESDIS
                                    : CHOLMOD_METIS; /* the default */
}

/* c->l = the analysis of a with c->cm's method (perm: CHOLMOD_GIVEN's). */
static int analyse(tf_ctx *ctx, tf_chol *c, const tf_csc *a, int *perm, tf_chol_info *info)
{
    cholmod_sparse s = wrap(a);
    openblas_set_num_threads(TF_BLAS_THREADS);
    double t0 = omp_get_wtime();
    c->l = perm ? cholmod_analyze_p(&s, perm, NULL, 0, &c->cm) : cholmod_analyze(&s, &c->cm);
    info->t_analyse += omp_get_wtime() - t0;
    info->t_factor = 0;
    if (c->l == NULL) {
        return tf_fail(ctx, "CHOLMOD analysis failed (status %d)%s", c->cm.status,
                       c->cm.status == CHOLMOD_OUT_OF_MEMORY ? ": out of memory" : "");
    }
    info->nnz_l = c->cm.lnz;
    info->flops = c->cm.fl;
    info->ordering = ordering_name(c->cm.method[c->cm.selected].ordering);
    info->rcond = 0;
    info->peak_bytes = (double)c->cm.memory_usage;
    return 0;
}

tf_chol *tf_chol_analyse(tf_ctx *ctx, const tf_csc *a, tf_ordering ord, int ldl, tf_chol_info *info)
{
    tf_chol *c = chol_new(ctx, a->n);
    if (c == NULL) {
        return NULL;
    }
    if (ldl) {
        c->cm.supernodal = CHOLMOD_SIMPLICIAL;
        c->cm.final_ll = 0;
    }
    c->cm.nmethods = 1;
    c->cm.method[0].ordering = cholmod_ordering(ord);
    info->t_analyse = 0;
    if (analyse(ctx, c, a, NULL, info) != 0) {
        tf_chol_free(c);
        return NULL;
    }
    return c;
}

tf_chol *tf_chol_analyse_last(tf_ctx *ctx, const tf_csc *a, tf_ordering ord,
                              const unsigned char *last, tf_chol_info *info)
{
    tf_chol *c = tf_chol_analyse(ctx, a, ord, 0, info);
    int *perm = c ? malloc(a->n * sizeof *perm) : NULL;
    if (perm == NULL) {
        if (c != NULL) {
            tf_fail(ctx, "out of memory");
        }
        tf_chol_free(c);
        return NULL;
    }
    const int *p0 = c->l->Perm;
    size_t k = 0;
    for (int pass = 0; pass < 2; ++pass) { /* the rest in the ordering's order, then `last` */
        for (size_t j = 0; j < a->n; ++j) {
            if ((last[p0[j]] != 0) == (pass == 1)) {
                perm[k++] = p0[j];
            }
        }
    }
    cholmod_free_factor(&c->l, &c->cm);
    c->cm.method[0].ordering = CHOLMOD_GIVEN;
    /* no postorder of the etree: it keeps descendants before ancestors but
     * may interleave `last` with subtrees that hang off it (with fixed DOFs
     * as isolated unit columns it did, and A was no longer last) */
    c->cm.postorder = 0;
    int rc = analyse(ctx, c, a, perm, info);
    free(perm);
    if (rc != 0) {
        tf_chol_free(c);
        return NULL;
    }
    return c;
}

double *tf_chol_trailing(tf_chol *c, size_t m, size_t *ld, const int **perm)
{
    cholmod_factor *l = c->l;
    if (l == NULL || !l->is_super || !l->is_ll || l->x == NULL || l->nsuper == 0 || m > c->n) {
        return NULL;
    }
    const int *super = l->super, *pi = l->pi, *px = l->px;
    size_t k = l->nsuper - 1, k1 = (size_t)super[k], ncol = (size_t)super[k + 1] - k1;
    size_t nrow = (size_t)(pi[k + 1] - pi[k]);
    if ((size_t)super[k + 1] != c->n || ncol < m || nrow != ncol) {
        return NULL; /* the last supernode is not the dense trailing block */
    }
    *ld = nrow;
    *perm = l->Perm;
    size_t off = ncol - m; /* A's first column within the supernode */
    return (double *)l->x + (size_t)px[k] + off + off * nrow;
}

int tf_chol_refactor(tf_ctx *ctx, tf_chol *c, const tf_csc *a, double *t)
{
    cholmod_sparse s = wrap(a);
    openblas_set_num_threads(TF_BLAS_THREADS);
    double t0 = omp_get_wtime();
    int ok = cholmod_factorize(&s, c->l, &c->cm);
    *t = omp_get_wtime() - t0;
    if (c->cm.status == CHOLMOD_NOT_POSDEF || (ok && c->l->minor < c->n)) {
        return 1;
    }
    if (!ok || c->cm.status != CHOLMOD_OK) {
        return tf_fail(ctx, "CHOLMOD factorisation failed (status %d)%s", c->cm.status,
                       c->cm.status == CHOLMOD_OUT_OF_MEMORY ? ": out of memory" : "");
    }
    return 0;
}

tf_chol *tf_chol_twin(tf_ctx *ctx, const tf_chol *c, const tf_csc *a)
{
    tf_chol *d = chol_new(ctx, c->n);
    int *perm = d ? malloc(c->n * sizeof *perm) : NULL;
    if (perm == NULL) {
        if (d != NULL) {
            tf_fail(ctx, "out of memory");
        }
        tf_chol_free(d);
        return NULL;
    }
    memcpy(perm, c->l->Perm, c->n * sizeof *perm);
    d->cm.supernodal = c->cm.supernodal;
    d->cm.final_ll = c->cm.final_ll;
    d->cm.nmethods = 1;
    d->cm.method[0].ordering = CHOLMOD_GIVEN;
    d->cm.postorder = 0; /* c's permutation is final (postordered, or kept as given) */
    tf_chol_info info = {0};
    int rc = analyse(ctx, d, a, perm, &info);
    free(perm);
    if (rc != 0) {
        tf_chol_free(d);
        return NULL;
    }
    return d;
}

double tf_chol_peak_bytes(const tf_chol *c) { return (double)c->cm.memory_usage; }

const char *tf_chol_ordering(const tf_chol *c)
{
    return ordering_name(c->cm.method[c->cm.selected].ordering);
}

void tf_chol_free(tf_chol *c)
{
    if (c == NULL) {
        return;
    }
    if (c->l != NULL) {
        cholmod_free_factor(&c->l, &c->cm);
    }
    cholmod_finish(&c->cm);
    free(c);
}
