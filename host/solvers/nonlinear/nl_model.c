/*
 * nl_model.c — what the nonlinear solver builds once (nl_internal.h): shape
 * functions, the cells' node sets and K's pattern, the gradients at every
 * Gauss point, loads, prescribed values, boundary points and the constant
 * part of the weak boundary terms.
 */
#include <cblas.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "solvers/assemble.h"
#include "solvers/cell_gradients.h"
#include "solvers/load_vector.h"
#include "problem/inclusions.h"
#include "solvers/nonlinear/nl_internal.h"

/* Gradients of every cell, in parallel (each cell its own slice). */
static int build_gradients(nl_solver *s, tf_ctx *ctx)
{
    size_t nc = s->ncell, np = s->np, failed = SIZE_MAX;
    s->gptr = malloc((nc + 1) * sizeof *s->gptr);
    s->wts = malloc(nc * np * sizeof *s->wts);
    if (s->gptr == NULL || s->wts == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    s->gptr[0] = 0;
    s->maxm = 0;
    for (size_t c = 0; c < nc; ++c) {
        size_t m = s->cs.ptr[c + 1] - s->cs.ptr[c];
        s->gptr[c + 1] = s->gptr[c] + 3 * np * m;
        s->maxm = m > s->maxm ? m : s->maxm;
    }
    s->grad = malloc((s->gptr[nc] + 1) * sizeof *s->grad);
    if (s->grad == NULL) {
        return tf_fail(ctx, "out of memory for the gradients at %zu Gauss points (%.0f MiB)",
                       nc * np, s->gptr[nc] * 8.0 / 1048576);
    }
    char msg[512] = "out of memory";
    double t0 = omp_get_wtime();
#pragma omp parallel num_threads(tf_ctx_threads(ctx))
    {
        tf_grad_work gw;
        int ok = tf_grad_work_init(&gw, &s->sh, s->sh.cloud->n) == 0;
#pragma omp for schedule(dynamic, 8)
        for (size_t c = 0; c < nc; ++c) {
            const uint32_t *set = s->cs.nodes + s->cs.ptr[c];
            size_t m = s->cs.ptr[c + 1] - s->cs.ptr[c];
            if (!ok || tf_cell_gradients(&s->sh, s->vci, &gw, c, set, m, s->grad + s->gptr[c]) != 0) {
#pragma omp critical(tf_nl_gradients)
                if (c < failed) {
                    failed = c;
                    snprintf(msg, sizeof msg, "%s", ok ? gw.sw.err : "out of memory");
                }
            } else {
                memcpy(s->wts + c * np, gw.w, np * sizeof *gw.w);
            }
        }
        if (ok) {
            tf_grad_work_free(&gw);
        }
    }
    s->t_setup_shape = omp_get_wtime() - t0;
    return failed == SIZE_MAX ? 0 : tf_fail(ctx, "%s", msg);
}

static int build_loads(nl_solver *s, const tf_problem *p, tf_ctx *ctx)
{
    size_t n3 = 3 * p->cloud.n;
    s->f0 = calloc(n3, sizeof *s->f0);
    s->basis = calloc(3 * n3 * (p->n_contacts + 1), sizeof *s->basis);
    if (s->f0 == NULL || s->basis == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t k = 0; k < p->n_loads; ++k) {
        const tf_load *ld = &p->loads[k];
        int rc = ld->exact ? tf_load_exact(ctx, &s->sh, p, &ld->patch, s->f0)
                           : tf_load_patch(ctx, &s->sh, &ld->patch, ld->force, s->f0);
        if (rc != 0) {
            return -1;
        }
    }
    for (size_t c = 0; c < p->n_contacts; ++c) {
        if (tf_load_patch(ctx, &s->sh, &p->contacts[c].patch, NULL, s->basis + 3 * n3 * c) != 0) {
            return -1;
        }
    }
    return 0;
}

/* Shape functions and gradients at every boundary point, and the constant
 * part of the weak terms (alpha or beta int phi_i phi_j S) in k's pattern. */
static int build_boundary(nl_solver *s, tf_ctx *ctx)
{
    const tf_boundary *b = &s->bnd;
    size_t cap = 64 * b->n + 16, used = 0;
    s->bptr = malloc((b->n + 1) * sizeof *s->bptr);
    s->bidx = malloc(cap * sizeof *s->bidx);
    s->bphi = malloc(cap * sizeof *s->bphi);
    s->bdphi = malloc(3 * cap * sizeof *s->bdphi);
    s->kbc = calloc(s->k.nnz + 1, sizeof *s->kbc);
    if (!s->bptr || !s->bidx || !s->bphi || !s->bdphi || !s->kbc) {
        return tf_fail(ctx, "out of memory");
    }
    tf_csc kb = s->k;
    kb.x = s->kbc;
    tf_shape_work w;
    tf_shape_work_init(&w);
    double *kl = NULL;
    int rc = 0;
    for (size_t q = 0; q < b->n && rc == 0; ++q) {
        const tf_bpoint *bp = &b->pt[q];
        if (tf_shape_at(&s->sh, &w, bp->x, bp->cell, 1) != 0) {
            rc = tf_fail(ctx, "boundary point (%g, %g, %g) mm: %s", bp->x[0], bp->x[1], bp->x[2],
                         w.err);
            break;
        }
        size_t n = w.n;
        if (used + n > cap) {
            cap = 2 * (used + n);
            s->bidx = realloc(s->bidx, cap * sizeof *s->bidx);
            s->bphi = realloc(s->bphi, cap * sizeof *s->bphi);
            s->bdphi = realloc(s->bdphi, 3 * cap * sizeof *s->bdphi);
            if (!s->bidx || !s->bphi || !s->bdphi) {
                rc = tf_fail(ctx, "out of memory");
                break;
            }
        }
        s->bptr[q] = used;
        memcpy(s->bidx + used, w.idx, n * sizeof *w.idx);
        memcpy(s->bphi + used, w.phi, n * sizeof *w.phi);
        memcpy(s->bdphi + 3 * used, w.dphi, 3 * n * sizeof *w.dphi);
        used += n;
        free(kl);
        kl = calloc(9 * n * n, sizeof *kl);
        if (kl == NULL) {
            rc = tf_fail(ctx, "out of memory");
            break;
        }
        for (size_t j = 0; j < n; ++j) {
            for (size_t i = 0; i < n; ++i) {
                for (size_t a = 0; a < 3; ++a) {
                    if ((bp->mask >> a) & 1u) {
                        kl[3 * n * (3 * j + a) + 3 * i + a] =
                            bp->w * s->bc_factor * w.phi[i] * w.phi[j];
                    }
                }
            }
        }
        if (tf_sparsity_add_dense(&kb, w.idx, n, kl) != 0) {
            rc = tf_fail(ctx, "a boundary point's support is not in the tangent's pattern");
        }
    }
    if (rc == 0) {
        s->bptr[b->n] = used;
    }
    free(kl);
    tf_shape_work_free(&w);
    return rc;
}

/* What the solver needs to know of the materials: their capabilities and
 * the quantities they provide (materials/material.h), never which law each
 * is.  Kinematics and volume measure are the body's (a region's law shares
 * them: tf_material_region_misfit); history, its size and an unsymmetric
 * tangent are any material's. */
static void law_constants(nl_solver *s)
{
    const tf_material *m = &s->mats[0];
    unsigned caps = 0;
    s->nh = 0;
    for (size_t k = 0; k < s->n_mats; ++k) {
        size_t h = tf_material_history_size(&s->mats[k]);
        caps |= tf_material_caps(&s->mats[k]);
        s->nh = h > s->nh ? h : s->nh;
    }
    s->relaxes = (caps & TF_MATERIAL_HISTORY) != 0;
    s->lin = tf_material_lame(m);
    s->lambda_v = s->bbar ? s->lin.lambda : 0;
    s->small = tf_material_kinematics(m) == TF_KIN_SMALL;
    s->trace_volume = !s->small && tf_material_volume(m) == TF_VOLUME_GREEN_TRACE;
    s->unsym = (caps & TF_MATERIAL_UNSYMMETRIC) != 0;
    s->hb = s->nh + (s->relaxes && s->bbar ? 2 : 0);
}

static int allocate_state(nl_solver *s, tf_ctx *ctx)
{
    size_t n3 = 3 * s->sh.cloud->n, pts = s->ncell * s->np, bpts = s->bnd.n;
    s->d = calloc(n3, sizeof *s->d);
    s->hist = calloc(pts * s->hb + 1, sizeof *s->hist);
    s->hist_new = calloc(pts * s->hb + 1, sizeof *s->hist_new);
    s->bhist = calloc(bpts * s->nh + 1, sizeof *s->bhist);
    s->bhist_new = calloc(bpts * s->nh + 1, sizeof *s->bhist_new);
    s->r = malloc(n3 * sizeof *s->r);
    s->fint = malloc(n3 * sizeof *s->fint);
    s->du = malloc(n3 * sizeof *s->du);
    s->dtrial = malloc(n3 * sizeof *s->dtrial);
    s->rtrial = malloc(n3 * sizeof *s->rtrial);
    if (s->unsym || s->base.opts.newton.tangent == TF_TANGENT_KRYLOV) {
        s->kskew = s->unsym ? calloc(s->k.nnz + 1, sizeof *s->kskew) : NULL;
        s->wk_cols = 40;
        s->wk = malloc((s->wk_cols + 6) * n3 * sizeof *s->wk);
    }
    if (s->base.opts.newton.tangent == TF_TANGENT_BFGS ||
        s->base.opts.newton.tangent == TF_TANGENT_PATCH) {
        s->qmax = 30;
        s->qs = malloc(s->qmax * n3 * sizeof *s->qs);
        s->qy = malloc(s->qmax * n3 * sizeof *s->qy);
        s->qrho = malloc(s->qmax * sizeof *s->qrho);
        if (!s->qs || !s->qy || !s->qrho) {
            return tf_fail(ctx, "out of memory");
        }
    }
    if (!s->d || !s->hist || !s->hist_new || !s->bhist || !s->bhist_new || !s->r || !s->fint ||
        !s->du || !s->dtrial || !s->rtrial || (s->unsym && !s->kskew) ||
        (s->wk_cols && !s->wk)) {
        return tf_fail(ctx, "out of memory");
    }
    return 0;
}

/* kf: k's pattern without the entries that couple a fixed DOF to another
 * one.  Elimination makes them zero, but CHOLMOD's analysis goes by the
 * pattern, so with them the factor of block48 at 41 x 41 x 9 held 1.15e8
 * entries against the linear solver's 9.99e7 (it drops the fixed DOFs:
 * tf_constraints_reduce), and 1.01e8 without (docs/validation.md §13).
 * The fixed DOFs stay, as unit diagonal entries: every vector keeps its
 * 3N layout. */
static int build_factored(nl_solver *s, tf_ctx *ctx)
{
    const tf_csc *k = &s->k;
    const unsigned char *fixed = s->bc.fixed;
    if (s->weak) {
        return 0;
    }
    s->kf.n = k->n; /* k's sizes bound kf's: one pass */
    s->kf.p = malloc((k->n + 1) * sizeof *s->kf.p);
    s->kf.i = malloc((k->nnz + 1) * sizeof *s->kf.i);
    s->kf.x = malloc((k->nnz + 1) * sizeof *s->kf.x);
    s->kf_at = malloc((k->nnz + 1) * sizeof *s->kf_at);
    if (!s->kf.p || !s->kf.i || !s->kf.x || !s->kf_at) {
        return tf_fail(ctx, "out of memory");
    }
    size_t e = 0;
    for (size_t j = 0; j < k->n; ++j) {
        s->kf.p[j] = (int)e;
        for (int q = k->p[j]; q < k->p[j + 1]; ++q) {
            size_t i = (size_t)k->i[q];
            if (i == j || (!fixed[i] && !fixed[j])) {
                s->kf.i[e] = (int)i;
                s->kf_at[e++] = (size_t)q;
            }
        }
    }
    s->kf.p[k->n] = (int)e;
    s->kf.nnz = e;
    return 0;
}

/* Material regions: each inclusion's material (the body's law or one of
 * the same kinematics and volume measure: tf_material_region_misfit). */
static int region_materials(nl_solver *s, const tf_problem *p, tf_ctx *ctx)
{
    s->n_mats = 1 + p->n_inclusions;
    for (size_t k = 0; k < p->n_inclusions; ++k) {
        const tf_inclusion *inc = &p->inclusions[k];
        const char *why = tf_material_region_misfit(&s->mats[0], &inc->material);
        if (why != NULL) {
            return tf_fail(ctx, "not yet: inclusion '%s' is %s in a %s body: %s", inc->name,
                           tf_material_name(&inc->material), tf_material_name(&s->mats[0]), why);
        }
        s->mats[1 + k] = inc->material;
    }
    if (p->n_inclusions > 0 && s->vci) {
        return tf_fail(ctx, "not yet: material regions with VCI integration (solver.integration: "
                            "gauss integrates them point by point)");
    }
    return 0;
}

/* Each material's volumetric modulus and relaxation function (law_constants
 * first: bbar, relaxes). */
static void material_constants(nl_solver *s)
{
    /* a law with history: each material relaxes with its own function;
     * a step of dt_relaxed relaxes the slowest of them (a static solve) */
    s->dt_relaxed = 0;
    for (size_t k = 0; k < s->n_mats; ++k) {
        s->lambda_m[k] = s->bbar ? tf_material_lame(&s->mats[k]).lambda : 0;
        s->vol_corr |= s->lambda_m[k] != 0;
        tf_material_relaxation(&s->mats[k], &s->g_inf[k], &s->tau[k]);
        if (s->relaxes && isfinite(s->tau[k])) {
            s->dt_relaxed = fmax(s->dt_relaxed, 1e15 * s->tau[k]);
        }
    }
}

/* The index into mats of inclusion k's material: the first of the body's
 * and the inclusions' with the same parameters (a cell is averaged per
 * material, cell_correction, and an inclusion of the body's own material
 * must leave the solve as it was, as in the linear B-bar). */
static unsigned material_index(const nl_solver *s, size_t k)
{
    for (size_t j = 0; j <= k; ++j) {
        const tf_material *a = &s->mats[j], *b = &s->mats[1 + k];
        if (a->law == b->law && memcmp(a->p, b->p, a->law->n_params * sizeof *a->p) == 0) {
            return (unsigned)j;
        }
    }
    return (unsigned)(1 + k);
}

/* The material index of every cell point and boundary point: the first
 * inclusion holding it, else the body (0). */
static unsigned material_at(const nl_solver *s, const tf_problem *p, const double x[3])
{
    size_t r = tf_problem_region_at(p, x);
    return r ? material_index(s, r - 1) : 0;
}

static int material_points(nl_solver *s, const tf_problem *p, tf_ctx *ctx)
{
    if (p->n_inclusions == 0) {
        return 0;
    }
    size_t n = s->ncell * s->np;
    s->pmat = malloc(n + 1);
    s->bmat = malloc(s->bnd.n + 1);
    if (s->pmat == NULL || s->bmat == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t c = 0; c < s->ncell; ++c) {
        for (size_t q = 0; q < s->np; ++q) {
            double x[3], w;
            tf_cells_point(&s->sh.cells, c, q, x, &w);
            s->pmat[c * s->np + q] = (unsigned char)material_at(s, p, x);
        }
    }
    for (size_t q = 0; q < s->bnd.n; ++q) {
        s->bmat[q] = (unsigned char)material_at(s, p, s->bnd.pt[q].x);
    }
    return 0;
}

int nl_model_build(nl_solver *s, const tf_problem *p, tf_ctx *ctx)
{
    const tf_solver_opts *o = &s->base.opts;
    double lo[3], hi[3];
    s->mats[0] = p->material;
    s->bbar = o->volumetric == TF_VOLUMETRIC_CELL;
    s->vci = o->integration == TF_INTEGRATION_VCI;
    if (region_materials(s, p, ctx) != 0) {
        return -1;
    }
    law_constants(s);
    material_constants(s);
    tf_problem_bounds(p, lo, hi);
    if (tf_shape_init(&s->sh, &p->cloud, lo, hi, o) != 0) {
        return tf_fail(ctx, "out of memory");
    }
    s->shape_ok = 1;
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    if (m != NULL && tf_shape_use_tets(ctx, &s->sh, m->tm.tet, m->tm.ntet, o->tet_degree) != 0) {
        return -1;
    }
    if (s->efg && tf_shape_use_efg(ctx, &s->sh) != 0) {
        return -1;
    }
    if (s->weak && tf_boundary_build(ctx, &s->bnd, p, &s->sh) != 0) {
        return -1;
    }
    s->ncell = tf_cells_count(&s->sh.cells);
    s->np = tf_cells_points(&s->sh.cells);
    if (material_points(s, p, ctx) != 0) {
        return -1;
    }
    tf_assembly_extra ex = {s->vci, s->weak ? &s->bnd : NULL, NULL};
    openblas_set_num_threads(1);
    if (tf_assemble_pattern(ctx, &s->sh, &ex, tf_ctx_threads(ctx), &s->cs, &s->bp, &s->k) != 0) {
        return -1;
    }
    if (build_gradients(s, ctx) != 0 || build_loads(s, p, ctx) != 0) {
        return -1;
    }
    if (tf_constraints_init(&s->bc, p) != 0) {
        return tf_fail(ctx, "out of memory");
    }
    if (build_factored(s, ctx) != 0) {
        return -1;
    }
    double scale = tf_boundary_scale(&s->lin, &p->cloud);
    s->bc_factor = scale * (o->bc == TF_BC_NITSCHE ? o->nitsche : o->penalty);
    if (s->weak && build_boundary(s, ctx) != 0) {
        return -1;
    }
    if (s->efg && tf_nodal_map_build(ctx, &s->map, &s->sh) != 0) {
        return -1;
    }
    if (allocate_state(s, ctx) != 0) {
        return -1;
    }
    return nl_patch_init(s);
}

void nl_model_free(nl_solver *s)
{
    if (s->shape_ok) {
        tf_shape_free(&s->sh);
    }
    tf_nodesets_free(&s->cs);
    tf_nodesets_free(&s->bp);
    tf_csc_free(&s->k);
    tf_csc_free(&s->kf);
    tf_boundary_free(&s->bnd);
    tf_constraints_release(&s->bc);
    tf_nodal_map_free(&s->map);
    tf_chol_free(s->chol);
    tf_chol_free(s->spare);
    tf_chol_free(s->ldl);
    nl_patch_free(&s->patch);
    void *bufs[] = {s->kf_at, s->gptr,  s->grad,  s->wts,       s->kskew, s->kbc,  s->d,      s->hist,
                    s->hist_new, s->bhist, s->bhist_new, s->bptr, s->bidx, s->bphi, s->bdphi,
                    s->f0,    s->basis, s->r,         s->fint,  s->du,   s->dtrial, s->rtrial,
                    s->wk,    s->qs,    s->qy,        s->qrho, s->pmat, s->bmat};
    for (size_t k = 0; k < sizeof bufs / sizeof bufs[0]; ++k) {
        free(bufs[k]);
    }
}
