/*
 * nodal_values.c — EFG's nodal parameters and nodal displacements
 * (nodal_values.h).
 */
#include "solvers/nodal_values.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <umfpack.h>

int tf_nodal_map_build(tf_ctx *ctx, tf_nodal_map *m, const tf_shape *sh)
{
    const tf_cloud *c = sh->cloud;
    memset(m, 0, sizeof *m);
    m->n = c->n;
    m->ptr = calloc(c->n + 1, sizeof *m->ptr);
    size_t cap = 32 * c->n + 16;
    m->col = malloc(cap * sizeof *m->col);
    m->val = malloc(cap * sizeof *m->val);
    tf_shape_work w;
    tf_shape_work_init(&w);
    int rc = m->ptr && m->col && m->val ? 0 : -1;
    for (size_t i = 0; i < c->n && rc == 0; ++i) {
        const double *x = c->xyz + 3 * i;
        if (tf_shape_at(sh, &w, x, tf_shape_cell(sh, x), 0) != 0) {
            tf_fail(ctx, "node %zu: %s", i + 1, w.err);
            rc = -2;
            break;
        }
        size_t q = m->ptr[i];
        if (q + w.n > cap) {
            cap = 2 * (q + w.n);
            int *nc = realloc(m->col, cap * sizeof *nc);
            double *nv = realloc(m->val, cap * sizeof *nv);
            m->col = nc ? nc : m->col;
            m->val = nv ? nv : m->val;
            if (!nc || !nv) {
                rc = -1;
                break;
            }
        }
        for (size_t k = 0; k < w.n; ++k) {
            if (w.phi[k] != 0) {
                m->col[q] = (int)w.idx[k];
                m->val[q++] = w.phi[k];
            }
        }
        m->ptr[i + 1] = q;
    }
    tf_shape_work_free(&w);
    if (rc == -1) {
        tf_fail(ctx, "out of memory for the nodal values of %zu nodes", c->n);
    }
    if (rc != 0) {
        tf_nodal_map_free(m);
        return -1;
    }
    return 0;
}

void tf_nodal_map_free(tf_nodal_map *m)
{
    if (m->numeric) {
        umfpack_di_free_numeric(&m->numeric);
    }
    if (m->symbolic) {
        umfpack_di_free_symbolic(&m->symbolic);
    }
    free(m->ptr);
    free(m->col);
    free(m->val);
    free(m->u_cache);
    free(m->d_cache);
    memset(m, 0, sizeof *m);
}

void tf_nodal_map_values(const tf_nodal_map *m, const double *d, double *u, size_t ncol)
{
    size_t n3 = 3 * m->n;
    for (size_t k = 0; k < ncol; ++k) {
        const double *dk = d + k * n3;
        double *uk = u + k * n3;
        for (size_t i = 0; i < m->n; ++i) {
            double s[3] = {0, 0, 0};
            for (size_t q = m->ptr[i]; q < m->ptr[i + 1]; ++q) {
                const double *dj = dk + 3 * (size_t)m->col[q];
                s[0] += m->val[q] * dj[0];
                s[1] += m->val[q] * dj[1];
                s[2] += m->val[q] * dj[2];
            }
            uk[3 * i] = s[0];
            uk[3 * i + 1] = s[1];
            uk[3 * i + 2] = s[2];
        }
    }
}

/* Row I of Lambda is column I of Lambda^T: the arrays are Lambda^T in
 * compressed columns, and UMFPACK_At solves with its transpose, Lambda. */
static int factorise(tf_ctx *ctx, tf_nodal_map *m)
{
    int n = (int)m->n;
    int *ap = malloc((m->n + 1) * sizeof *ap);
    if (ap == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t i = 0; i <= m->n; ++i) {
        ap[i] = (int)m->ptr[i];
    }
    int st = umfpack_di_symbolic(n, n, ap, m->col, m->val, &m->symbolic, NULL, NULL);
    if (st == UMFPACK_OK) {
        st = umfpack_di_numeric(ap, m->col, m->val, m->symbolic, &m->numeric, NULL, NULL);
    }
    free(ap);
    if (st != UMFPACK_OK) {
        return tf_fail(
            ctx,
            "the EFG shape functions at the nodes form a singular matrix (UMFPACK status "
            "%d): nodal displacements cannot be turned into parameters",
            st);
    }
    return 0;
}

int tf_nodal_map_params(tf_ctx *ctx, tf_nodal_map *m, const double *u, double *d)
{
    if (m->numeric == NULL && factorise(ctx, m) != 0) {
        return -1;
    }
    double *b = malloc(2 * m->n * sizeof *b);
    int *ap = malloc((m->n + 1) * sizeof *ap);
    if (b == NULL || ap == NULL) {
        free(b);
        free(ap);
        return tf_fail(ctx, "out of memory");
    }
    for (size_t i = 0; i <= m->n; ++i) {
        ap[i] = (int)m->ptr[i];
    }
    double *x = b + m->n;
    int st = UMFPACK_OK;
    for (int a = 0; a < 3 && st == UMFPACK_OK; ++a) {
        for (size_t i = 0; i < m->n; ++i) {
            b[i] = u[3 * i + (size_t)a];
        }
        st = umfpack_di_solve(UMFPACK_At, ap, m->col, m->val, x, b, m->numeric, NULL, NULL);
        for (size_t i = 0; i < m->n; ++i) {
            d[3 * i + (size_t)a] = x[i];
        }
    }
    free(b);
    free(ap);
    if (st != UMFPACK_OK) {
        return tf_fail(ctx, "UMFPACK solve failed (status %d)", st);
    }
    return 0;
}

const double *tf_nodal_map_params_of(tf_ctx *ctx, tf_nodal_map *m, const double *u)
{
    size_t n3 = 3 * m->n;
    const double *d = NULL;
#pragma omp critical(tf_nodal_map_cache)
    {
        if (m->d_cache == NULL) {
            m->d_cache = malloc(n3 * sizeof *m->d_cache);
            m->u_cache = malloc(n3 * sizeof *m->u_cache);
        }
        if (m->d_cache == NULL || m->u_cache == NULL) {
            tf_fail(ctx, "out of memory");
        } else if (m->cache_ok && memcmp(m->u_cache, u, n3 * sizeof *u) == 0) {
            d = m->d_cache;
        } else {
            m->cache_ok = 0;
            if (tf_nodal_map_params(ctx, m, u, m->d_cache) == 0) {
                memcpy(m->u_cache, u, n3 * sizeof *u);
                m->cache_ok = 1;
                d = m->d_cache;
            }
        }
    }
    return d;
}
