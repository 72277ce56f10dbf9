/*
 * region_surface.c — the region's surface model: POD modes, amplitudes and
 * site modes per site, their splines, evaluation (region_surface.h).
 */
#include "fitting/region_surface.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "numerics/grid_spline.h"
#include "numerics/pod.h"

/* Modes whose singular value is below this fraction of the first carry
 * rounding, not data. */
#define SIGMA_FLOOR 1e-12

void tf_region_modes_free(tf_region_modes *m)
{
    free(m->phi);
    free(m->sigma);
    free(m->amp);
    free(m->site);
    free(m->near.out_q);
    free(m->near.site_q);
    memset(m, 0, sizeof *m);
}

/* amp (r_max x 3 per site) = R_F Phi^T U_s. */
static void amplitudes(const tf_region_sites *t, const size_t *idx, size_t n, double R_F,
                       tf_region_modes *m)
{
    size_t rows = 3 * t->n_out, r = m->r_max;
    for (size_t s = 0; s < n; ++s) {
        const double *U = t->U + 9 * t->n_out * idx[s];
        for (size_t k = 0; k < r; ++k) {
            for (int l = 0; l < 3; ++l) {
                double sum = 0;
                for (size_t i = 0; i < rows; ++i) {
                    sum += m->phi[k * rows + i] * U[(size_t)l * rows + i];
                }
                m->amp[(s * r + k) * 3 + (size_t)l] = R_F * sum;
            }
        }
    }
}

/* The site modes: Psi_k = K^-1 sum_j L_j c_jk solved, then L_s^T Psi. */
static int site_modes(tf_ctx *ctx, tf_solver *s, const tf_region_sites *t, const size_t *idx,
                      size_t n, double R_F, tf_region_modes *m)
{
    size_t r = m->r_max, n3 = 3 * tf_solver_node_count(s);
    double *coef = malloc(3 * n * r * sizeof *coef), *psi = malloc(n3 * r * sizeof *psi);
    if (!coef || !psi) {
        free(coef);
        free(psi);
        return tf_fail(ctx, "out of memory for %zu site modes", r);
    }
    for (size_t k = 0; k < r; ++k) {
        double s2 = m->sigma[k] * m->sigma[k];
        for (size_t j = 0; j < n; ++j) {
            for (int l = 0; l < 3; ++l) { /* Phi_k^T U_j e_l / sigma_k^2 */
                coef[k * 3 * n + 3 * j + (size_t)l] = m->amp[(j * r + k) * 3 + (size_t)l] /
                                                       (R_F * s2);
            }
        }
    }
    double t0 = omp_get_wtime();
    int rc = tf_region_sites_combine(ctx, s, t, idx, n, coef, r, psi);
    m->seconds_solve = omp_get_wtime() - t0;
    for (size_t j = 0; rc == 0 && j < n; ++j) {
        for (size_t k = 0; k < r; ++k) {
            double avg[3];
            tf_region_sites_average(t, idx[j], psi + k * n3, avg);
            for (int i = 0; i < 3; ++i) {
                m->site[(j * 3 + (size_t)i) * r + k] = avg[i];
            }
        }
    }
    free(coef);
    free(psi);
    return rc;
}

int tf_region_modes_build(tf_ctx *ctx, tf_solver *s, const tf_region_sites *t, const size_t *idx,
                          size_t n, double R_F, unsigned r_max, tf_region_modes *m)
{
    memset(m, 0, sizeof *m);
    size_t rows = 3 * t->n_out, cols = 3 * n;
    double *data = malloc(rows * cols * sizeof *data);
    if (data == NULL) {
        return tf_fail(ctx, "out of memory for the POD of %zu sites", n);
    }
    for (size_t j = 0; j < n; ++j) {
        memcpy(data + 3 * j * rows, t->U + 9 * t->n_out * idx[j], 3 * rows * sizeof *data);
    }
    tf_pod pod;
    int rc = tf_pod_compute(ctx, data, (int)rows, (int)cols, &pod);
    free(data);
    if (rc != 0) {
        return -1;
    }
    unsigned r = r_max < (unsigned)pod.k ? r_max : (unsigned)pod.k;
    r = r < TF_REGION_MAX_RANK ? r : TF_REGION_MAX_RANK;
    while (r > 1 && !(pod.sigma[r - 1] > SIGMA_FLOOR * pod.sigma[0])) {
        r--;
    }
    m->n_sites = n;
    m->n_out = t->n_out;
    m->r_max = r;
    m->phi = malloc(rows * r * sizeof *m->phi);
    m->sigma = malloc(r * sizeof *m->sigma);
    m->amp = malloc(3 * n * r * sizeof *m->amp);
    m->site = malloc(3 * n * r * sizeof *m->site);
    if (!m->phi || !m->sigma || !m->amp || !m->site) {
        tf_pod_free(&pod);
        tf_region_modes_free(m);
        return tf_fail(ctx, "out of memory");
    }
    memcpy(m->phi, pod.modes, rows * r * sizeof *m->phi);
    memcpy(m->sigma, pod.sigma, r * sizeof *m->sigma);
    tf_pod_free(&pod);
    amplitudes(t, idx, n, R_F, m);
    if (site_modes(ctx, s, t, idx, n, R_F, m) != 0) {
        tf_region_modes_free(m);
        return -1;
    }
    return 0;
}

void tf_region_surface_free(tf_region_surface *s)
{
    free(s->modes);
    free(s->ctrl);
    free(s->near_idx);
    free(s->near_D);
    s->modes = s->ctrl = s->near_D = NULL;
    s->near_idx = NULL;
    s->n_near = 0;
}

/* The residual responses R_s = U_s - Phi Phi^T U_s (3 n_out x 3,
 * column-major) of the modes' sites, per unit force (mm/N). */
static void residuals(const tf_region_modes *m, unsigned r, double *res)
{
    const tf_region_sites *t = m->near.t;
    size_t rows = 3 * m->n_out;
#pragma omp parallel for schedule(static)
    for (size_t s = 0; s < m->n_sites; ++s) {
        const double *U = t->U + 9 * t->n_out * m->near.idx[s];
        double *R = res + s * 3 * rows;
        memcpy(R, U, 3 * rows * sizeof *R);
        for (int l = 0; l < 3; ++l) {
            for (size_t k = 0; k < r; ++k) {
                const double *phi = m->phi + k * rows;
                double c = 0;
                for (size_t i = 0; i < rows; ++i) {
                    c += phi[i] * U[(size_t)l * rows + i];
                }
                for (size_t i = 0; i < rows; ++i) {
                    R[(size_t)l * rows + i] -= c * phi[i];
                }
            }
        }
    }
}

typedef struct near_pick {
    double d;
    uint32_t j;
} near_pick;

static int by_distance(const void *a, const void *b)
{
    const near_pick *x = a, *y = b;
    if (x->d != y->d) {
        return x->d > y->d ? 1 : -1;
    }
    return (x->j > y->j) - (x->j < y->j);
}

/* Control point c's reference point: (i ha, j hb) at the height of its
 * nearest site. */
static void control_point(const tf_region_near_spec *nr, unsigned nx, unsigned ny,
                          const double h[2], size_t c, double q[3])
{
    long i = (long)(c % (nx + 2)) - 1, j = (long)(c / (nx + 2)) - 1;
    long si = i < 0 ? 0 : i >= (long)nx ? (long)nx - 1 : i;
    long sj = j < 0 ? 0 : j >= (long)ny ? (long)ny - 1 : j;
    q[0] = (double)i * h[0];
    q[1] = (double)j * h[1];
    q[2] = nr->site_q[3 * ((size_t)sj * nx + (size_t)si) + 2];
}

/* The near field of a surface of rank r (region_surface.h): the residuals'
 * splines, each control point's outputs within the radius (the nearest
 * cap of them), padded to the largest count. */
static int near_fit(tf_ctx *ctx, const tf_region_modes *m, unsigned r, tf_region_surface *out)
{
    const tf_region_near_spec *nr = &m->near;
    size_t n = m->n_sites, rows = 3 * m->n_out, q = 3 * rows;
    size_t ncp = (size_t)(out->nx + 2) * (out->ny + 2);
    unsigned cap = nr->cap < TF_REGION_MAX_NEAR ? nr->cap : TF_REGION_MAX_NEAR;
    double *res = malloc(n * q * sizeof *res), *ctrl = malloc(ncp * q * sizeof *ctrl);
    near_pick *pick = malloc(ncp * cap * sizeof *pick), *cand = malloc(m->n_out * sizeof *cand);
    unsigned *count = calloc(ncp, sizeof *count);
    if (!res || !ctrl || !pick || !cand || !count) {
        free(res); free(ctrl); free(pick); free(cand); free(count);
        return tf_fail(ctx, "out of memory for the near field");
    }
    residuals(m, r, res);
    int rc = tf_spline_interpolate(ctx, out->nx, out->ny, q, res, ctrl);
    unsigned most = 0;
    for (size_t c = 0; rc == 0 && c < ncp; ++c) {
        double cq[3];
        control_point(nr, out->nx, out->ny, out->h, c, cq);
        size_t k = 0;
        for (size_t j = 0; j < m->n_out; ++j) {
            const double *o = nr->out_q + 3 * j;
            double d = sqrt((o[0] - cq[0]) * (o[0] - cq[0]) + (o[1] - cq[1]) * (o[1] - cq[1]) +
                            (o[2] - cq[2]) * (o[2] - cq[2]));
            if (d <= nr->radius) {
                cand[k++] = (near_pick){d, (uint32_t)j};
            }
        }
        qsort(cand, k, sizeof *cand, by_distance);
        count[c] = (unsigned)(k < cap ? k : cap);
        memcpy(pick + c * cap, cand, count[c] * sizeof *cand);
        most = count[c] > most ? count[c] : most;
    }
    out->n_near = most;
    out->near_radius = nr->radius;
    out->near_idx = calloc(ncp * most + 1, sizeof *out->near_idx);
    out->near_D = calloc(9 * ncp * most + 1, sizeof *out->near_D);
    if (rc == 0 && (!out->near_idx || !out->near_D)) {
        rc = tf_fail(ctx, "out of memory for the near field");
    }
    for (size_t c = 0; rc == 0 && c < ncp; ++c) {
        for (unsigned e = 0; e < count[c]; ++e) {
            uint32_t j = pick[c * cap + e].j;
            double *D = out->near_D + 9 * (c * most + e);
            out->near_idx[c * most + e] = j;
            for (size_t i = 0; i < 3; ++i) {
                for (size_t l = 0; l < 3; ++l) {
                    D[3 * i + l] = ctrl[c * q + l * rows + 3 * j + i];
                }
            }
        }
    }
    free(res); free(ctrl); free(pick); free(cand); free(count);
    return rc;
}

int tf_region_surface_fit(tf_ctx *ctx, const tf_region_modes *m, unsigned nx, unsigned ny,
                          const double h[2], double R_F, unsigned r, tf_region_surface *out)
{
    memset(out, 0, sizeof *out);
    size_t n = (size_t)nx * ny, rows = 3 * m->n_out, q = 6 * (size_t)r, R = m->r_max;
    if (n != m->n_sites || r < 1 || r > m->r_max) {
        return tf_fail(ctx, "a surface of rank %u from %u modes of %zu sites (grid %u x %u)", r,
                       m->r_max, m->n_sites, nx, ny);
    }
    double *site = malloc(n * q * sizeof *site);
    out->modes = malloc(rows * r * sizeof *out->modes);
    out->ctrl = malloc((size_t)(nx + 2) * (ny + 2) * q * sizeof *out->ctrl);
    if (!site || !out->modes || !out->ctrl) {
        free(site);
        tf_region_surface_free(out);
        return tf_fail(ctx, "out of memory");
    }
    for (size_t s = 0; s < n; ++s) {
        double *v = site + s * q;
        for (size_t k = 0; k < r; ++k) {
            for (int l = 0; l < 3; ++l) {
                v[3 * k + (size_t)l] = m->amp[(s * R + k) * 3 + (size_t)l];  /* A: r x 3 */
                v[3 * r + (size_t)l * r + k] = m->site[(s * 3 + (size_t)l) * R + k]; /* 3 x r */
            }
        }
    }
    memcpy(out->modes, m->phi, rows * r * sizeof *out->modes);
    out->nx = nx;
    out->ny = ny;
    out->h[0] = h[0];
    out->h[1] = h[1];
    out->r = r;
    out->n_out = m->n_out;
    out->R_F = R_F;
    int rc = tf_spline_interpolate(ctx, nx, ny, q, site, out->ctrl);
    free(site);
    if (rc == 0 && m->near.radius > 0) {
        rc = near_fit(ctx, m, r, out);
    }
    if (rc != 0) {
        tf_region_surface_free(out);
    }
    return rc;
}

/* out += the near field at (a, b) under force F (N). */
static void near_eval(const tf_region_surface *s, double a, double b, const double F[3],
                      double *out)
{
    unsigned ci[2];
    double t[2], w[2][4];
    const double g[2] = {a / s->h[0], b / s->h[1]};
    const unsigned n[2] = {s->nx, s->ny};
    for (int x = 0; x < 2; ++x) {
        tf_bspline_cell(g[x], n[x], &ci[x], &t[x]);
        tf_bspline_weights(t[x], w[x], NULL);
    }
    for (size_t l = 0; l < 4; ++l) {
        for (size_t k = 0; k < 4; ++k) {
            size_t c = (ci[1] + l) * (s->nx + 2) + ci[0] + k;
            double wt = w[1][l] * w[0][k];
            for (unsigned e = 0; e < s->n_near; ++e) {
                const double *D = s->near_D + 9 * (c * s->n_near + e);
                size_t j = s->near_idx[c * s->n_near + e];
                for (size_t i = 0; i < 3; ++i) {
                    out[3 * j + i] += wt * (D[3 * i] * F[0] + D[3 * i + 1] * F[1] +
                                            D[3 * i + 2] * F[2]);
                }
            }
        }
    }
}

void tf_region_surface_eval(const tf_region_surface *s, double a, double b, const double F[3],
                            double *out)
{
    size_t q = 6 * (size_t)s->r, rows = 3 * s->n_out;
    double c[6 * TF_REGION_MAX_RANK], ak[TF_REGION_MAX_RANK];
    tf_spline_eval(s->nx, s->ny, q, s->ctrl, a / s->h[0], b / s->h[1], c, NULL, NULL);
    for (size_t k = 0; k < s->r; ++k) {
        ak[k] = (c[3 * k] * F[0] + c[3 * k + 1] * F[1] + c[3 * k + 2] * F[2]) / s->R_F;
    }
    for (size_t i = 0; i < rows; ++i) {
        double sum = 0;
        for (size_t k = 0; k < s->r; ++k) {
            sum += s->modes[k * rows + i] * ak[k];
        }
        out[i] = sum;
    }
    if (s->n_near > 0) {
        near_eval(s, a, b, F, out);
    }
}

void tf_region_surface_cross(const tf_region_surface *s, double a1, double b1, double a2,
                             double b2, double C[9])
{
    size_t q = 6 * (size_t)s->r, r = s->r;
    double c1[6 * TF_REGION_MAX_RANK], c2[6 * TF_REGION_MAX_RANK];
    tf_spline_eval(s->nx, s->ny, q, s->ctrl, a1 / s->h[0], b1 / s->h[1], c1, NULL, NULL);
    tf_spline_eval(s->nx, s->ny, q, s->ctrl, a2 / s->h[0], b2 / s->h[1], c2, NULL, NULL);
    for (int i = 0; i < 3; ++i) {
        for (int l = 0; l < 3; ++l) {
            double sum = 0;
            for (size_t k = 0; k < r; ++k) {
                sum += c1[3 * r + (size_t)i * r + k] * c2[3 * k + (size_t)l];
            }
            C[3 * i + l] = sum / s->R_F;
        }
    }
}

size_t tf_region_surface_floats(const tf_region_surface *s)
{
    return 12 + 3 + 3 * s->n_out * s->r +
           (size_t)(s->nx + 2) * (s->ny + 2) * (6 * (size_t)s->r + 10 * (size_t)s->n_near);
}
