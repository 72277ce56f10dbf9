/*
 * region_cases.c — a contact region's load cases for a solver that is not
 * affine, and the per-site potential fit (region_cases.h).
 */
#include "fitting/region_cases.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitting/case_graph.h"
#include "fitting/region_law.h"
#include "numerics/lsq.h"
#include "problem/region_chart.h"

void tf_region_cases_free(tf_region_cases *c)
{
    for (size_t k = 0; c->problem.contacts && k < c->problem.n_contacts; ++k) {
        tf_patch_release(&c->problem.contacts[k].patch);
    }
    free(c->problem.contacts);
    free(c->ab);
    free(c->force);
    free(c->force_scene);
    free(c->from);
    free(c->keep);
    memset(c, 0, sizeof *c);
}

int tf_region_cases_build(tf_ctx *ctx, const tf_problem *p, int contact, const double *ab,
                          size_t n, const double (*force)[3], size_t n_force, tf_region_cases *c)
{
    memset(c, 0, sizeof *c);
    const tf_contact_region *r = &p->contacts[contact].region;
    size_t n3 = 3 * p->cloud.n;
    c->problem = *p;
    c->region = r;
    c->n_sites = n;
    c->n_force = n_force;
    c->problem.contacts = calloc(n + 1, sizeof *c->problem.contacts);
    c->problem.n_contacts = 0;
    c->ab = malloc((2 * n + 1) * sizeof *c->ab);
    c->force = malloc((n_force + 1) * sizeof *c->force);
    c->force_scene = malloc((n_force + 1) * sizeof *c->force_scene);
    c->from = malloc((n_force + 1) * sizeof *c->from);
    c->keep = malloc((n3 + 1) * sizeof *c->keep);
    if (!c->problem.contacts || !c->ab || !c->force || !c->force_scene || !c->from || !c->keep) {
        tf_region_cases_free(c);
        return tf_fail(ctx, "out of memory");
    }
    memcpy(c->ab, ab, 2 * n * sizeof *ab);
    memcpy(c->force, force, n_force * sizeof *force);
    for (size_t k = 0; k < n_force; ++k) { /* F_scene = R^T F */
        for (int a = 0; a < 3; ++a) {
            c->force_scene[k][a] = r->chart.R[a] * force[k][0] + r->chart.R[3 + a] * force[k][1] +
                                   r->chart.R[6 + a] * force[k][2];
        }
    }
    for (size_t d = 0; d < n3; ++d) {
        c->keep[d] = d;
    }
    tf_case_graph_anchored((const double(*)[3])c->force_scene, n_force,
                           tf_case_graph_anchors(n_force), c->from);
    for (size_t k = 0; k < n; ++k) {
        tf_contact *t = &c->problem.contacts[k];
        snprintf(t->name, sizeof t->name, "site%zu", k + 1);
        if (tf_region_site_patch(ctx, p, r, ab[2 * k], ab[2 * k + 1], &t->patch, t->at) != 0) {
            tf_region_cases_free(c);
            return -1;
        }
        t->node = tf_problem_nearest_node(p, t->at);
        c->problem.n_contacts = k + 1;
    }
    return 0;
}

void tf_region_cases_list(const tf_region_cases *c, size_t site, tf_case_list *l)
{
    *l = (tf_case_list){.contact = (int)site,
                        .n = c->n_force,
                        .force = (const double(*)[3])c->force_scene,
                        .from = c->from,
                        .n_keep = 3 * c->problem.cloud.n,
                        .keep = c->keep};
}

int tf_region_cases_average(tf_ctx *ctx, const tf_solver *s, const tf_region_cases *c,
                            size_t site, const double *u, double out[3])
{
    const tf_patch *pt = &c->problem.contacts[site].patch;
    double *x = malloc((3 * pt->n_pts + 1) * sizeof *x), *uh = malloc((3 * pt->n_pts + 1) * sizeof *uh);
    double *grad = malloc((9 * pt->n_pts + 1) * sizeof *grad);
    if (!x || !uh || !grad) {
        free(x);
        free(uh);
        free(grad);
        return tf_fail(ctx, "out of memory");
    }
    for (size_t k = 0; k < pt->n_pts; ++k) {
        memcpy(x + 3 * k, pt->pts + 4 * k, 3 * sizeof *x);
    }
    int rc = tf_solver_field(ctx, s, u, x, pt->n_pts, uh, grad);
    double avg[3] = {0, 0, 0};
    for (size_t k = 0; rc == 0 && k < pt->n_pts; ++k) {
        for (int a = 0; a < 3; ++a) {
            avg[a] += pt->pts[4 * k + 3] * uh[3 * k + (size_t)a] / pt->area;
        }
    }
    for (int k = 0; k < 3; ++k) {
        const double *e = c->region->chart.R + 3 * k;
        out[k] = e[0] * avg[0] + e[1] * avg[1] + e[2] * avg[2];
    }
    free(x);
    free(uh);
    free(grad);
    return rc;
}

/* d^(o0 + o1 + o2) (v0^e0 v1^e1 v2^e2) / dv0^o0 dv1^o1 dv2^o2. */
static double term_derivative(const unsigned e[3], const double v[3], const unsigned o[3])
{
    double d = 1;
    for (int a = 0; a < 3; ++a) {
        if (o[a] > e[a]) {
            return 0;
        }
        for (unsigned k = 0; k < o[a]; ++k) {
            d *= e[a] - k;
        }
        for (unsigned k = o[a]; k < e[a]; ++k) {
            d *= v[a];
        }
    }
    return d;
}

void tf_region_potential_force(unsigned P, double s_u, const double *e, const double u[3],
                               double F[3])
{
    unsigned ex[TF_REGION_MAX_TERMS][3];
    size_t T = tf_region_terms(P);
    double v[3] = {s_u * u[0], s_u * u[1], s_u * u[2]};
    tf_region_exponents(P, ex);
    for (int a = 0; a < 3; ++a) {
        unsigned o[3] = {0, 0, 0};
        o[a] = 1;
        double g = 0;
        for (size_t t = 0; t < T; ++t) {
            g += e[t] * term_derivative(ex[t], v, o);
        }
        F[a] = s_u * g;
    }
}

double tf_region_potential_min_curvature(unsigned P, double s_u, const double *e,
                                         const double u[3])
{
    unsigned ex[TF_REGION_MAX_TERMS][3];
    size_t T = tf_region_terms(P);
    double v[3] = {s_u * u[0], s_u * u[1], s_u * u[2]}, H[9], lam[3];
    tf_region_exponents(P, ex);
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
            unsigned o[3] = {0, 0, 0};
            o[a]++;
            o[b]++;
            double h = 0;
            for (size_t t = 0; t < T; ++t) {
                h += e[t] * term_derivative(ex[t], v, o);
            }
            H[3 * a + b] = s_u * s_u * h;
        }
    }
    tf_sym3_eigenvalues(H, lam);
    return lam[0];
}

int tf_region_potential_fit(tf_ctx *ctx, unsigned P, double s_u, const double (*u)[3],
                            const double (*F)[3], size_t m, double *e, double *rms)
{
    unsigned ex[TF_REGION_MAX_TERMS][3];
    size_t T = tf_region_terms(P), rows = 3 * m;
    if (P < 2 || P > TF_REGION_MAX_P) {
        return tf_fail(ctx, "a potential of degree %u: 2 to %d", P, TF_REGION_MAX_P);
    }
    tf_region_exponents(P, ex);
    double *A = malloc(rows * T * sizeof *A), *y = malloc(rows * sizeof *y), rss;
    if (!A || !y) {
        free(A);
        free(y);
        return tf_fail(ctx, "out of memory");
    }
    for (size_t i = 0; i < m; ++i) {
        double v[3] = {s_u * u[i][0], s_u * u[i][1], s_u * u[i][2]};
        for (int a = 0; a < 3; ++a) {
            unsigned o[3] = {0, 0, 0};
            o[a] = 1;
            for (size_t t = 0; t < T; ++t) {
                A[t * rows + 3 * i + (size_t)a] = s_u * term_derivative(ex[t], v, o);
            }
            y[3 * i + (size_t)a] = F[i][a];
        }
    }
    tf_lsq *f = tf_lsq_factor(ctx, rows, T, A, rows, NULL, 1e-12);
    int rc = f == NULL ? -1 : tf_lsq_solve(ctx, f, 1, y, rows, e, T, &rss);
    if (rc == 0 && rms != NULL) {
        *rms = sqrt(rss / (double)m);
    }
    tf_lsq_free(f);
    free(A);
    free(y);
    return rc;
}
