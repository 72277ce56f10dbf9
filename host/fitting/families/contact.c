/*
 * contact.c — the contact inverse (haptic impedance): force at the
 * contact site as a polynomial of the contact site's displacement.
 *
 * The input map uses the contact stiffness: a linear fit delta = delta0 + C f
 * gives K = C^-1, and g = K (delta - delta_c) / R with delta_c the
 * displacement at the envelope centre, so g is the normalised force for a
 * linear tissue and the envelope in displacement is exactly the image of the
 * force ball.  The polynomial then only has to carry the nonlinearity.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"

extern const tf_family tf_family_contact;

/* Inverse of a 3x3 row-major matrix; returns its reciprocal condition
 * estimate |det| / (||c||^3) (0 when singular). */
static double inverse3(const double c[9], double k[9])
{
    double co[9] = {c[4] * c[8] - c[5] * c[7], c[5] * c[6] - c[3] * c[8], c[3] * c[7] - c[4] * c[6],
                    c[2] * c[7] - c[1] * c[8], c[0] * c[8] - c[2] * c[6], c[1] * c[6] - c[0] * c[7],
                    c[1] * c[5] - c[2] * c[4], c[2] * c[3] - c[0] * c[5], c[0] * c[4] - c[1] * c[3]};
    double det = c[0] * co[0] + c[1] * co[1] + c[2] * co[2];
    double norm = 0;
    for (int i = 0; i < 9; ++i) {
        norm = fmax(norm, fabs(c[i]));
    }
    if (det == 0 || norm == 0) {
        return 0;
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            k[3 * i + j] = co[3 * j + i] / det; /* adjugate is the transposed cofactor matrix */
        }
    }
    return fabs(det) / (norm * norm * norm);
}

/* delta = delta0 + C f over the selected cases. */
static int linear_compliance(tf_ctx *ctx, const tf_fitdata *d, const size_t *idx, size_t m,
                             double delta0[3], double c[9])
{
    double *a = malloc(m * 4 * sizeof *a), *y = malloc(m * 3 * sizeof *y), x[12];
    if (a == NULL || y == NULL) {
        free(a);
        free(y);
        return tf_fail(ctx, "contact: out of memory");
    }
    for (size_t i = 0; i < m; ++i) {
        size_t n = tf_family_case(idx, i);
        a[i] = 1;
        for (int k = 0; k < 3; ++k) {
            a[i + (size_t)(k + 1) * m] = d->force[n][k];
            y[i + (size_t)k * m] = d->contact[n][k];
        }
    }
    int rc = tf_family_lsq(ctx, a, m, 4, y, 3, x);
    free(a);
    free(y);
    if (rc == 0) {
        for (int i = 0; i < 3; ++i) {
            delta0[i] = x[4 * i];
            for (int k = 0; k < 3; ++k) {
                c[3 * i + k] = x[4 * i + 1 + k];
            }
        }
    }
    return rc;
}

/* The device projects a displacement outside its map's envelope onto it
 * (tfit_input.c: |W (delta - x0)| <= 1).  For a tissue whose response is
 * affine the training displacements fill that unit ball exactly (g is the
 * normalised force).  A nonlinear tissue's reach beyond it where the tissue
 * is softer than its linear fit (neo-Hookean block48 pressed down), and the
 * device would clamp displacements that forces inside the envelope cause:
 * the map is then widened so that the farthest training displacement sits
 * at 1 / (1 + REACH_MARGIN) of the envelope's radius (the margin for
 * displacements between the training cases'). */
#define REACH_MARGIN 0.05
static void widen_to_reach(tf_model *model, const tf_fitdata *d, const size_t *idx, size_t m,
                             const double x0[3], double w[9])
{
    double reach = 0;
    for (size_t i = 0; i < m; ++i) {
        double g[3];
        tf_family_normalise(model, d->contact[tf_family_case(idx, i)], g);
        reach = fmax(reach, sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
    }
    if (!(reach > 1 + 1e-3)) {
        return;
    }
    const double widen = reach * (1 + REACH_MARGIN);
    for (int i = 0; i < 9; ++i) {
        w[i] /= widen;
    }
    tf_model_set_map(model, x0, w);
}

static tf_model *fit(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders)
{
    const tf_fitdata *d = &c->train;
    const uint32_t p = orders[0];
    if (idx == NULL) {
        m = d->n_cases;
    }
    double delta0[3], cm[9], k[9], w[9], x0[3];
    double(*g)[3] = malloc(m * sizeof *g);
    if (g == NULL) {
        tf_fail(ctx, "contact: out of memory");
        return NULL;
    }
    for (size_t i = 0; i < m; ++i) { /* forces normalised to the envelope */
        for (int a = 0; a < 3; ++a) {
            g[i][a] = (d->force[tf_family_case(idx, i)][a] - d->centre[a]) / d->radius;
        }
    }
    int spans = tf_family_spans(ctx, NULL, (const double(*)[3])g, NULL, m);
    free(g);
    if (spans != 0 || linear_compliance(ctx, d, idx, m, delta0, cm) != 0) {
        return NULL;
    }
    if (inverse3(cm, k) < 1e-12) {
        tf_fail(ctx, "contact: the contact site's compliance is singular (the site does not move "
                     "under some force direction): no impedance model");
        return NULL;
    }
    tf_model *model = tf_model_new(ctx, "contact", TFIT_FAMILY_CONTACT, 1, &p, 1);
    if (model == NULL) {
        return NULL;
    }
    for (int i = 0; i < 3; ++i) {
        x0[i] = delta0[i];
        for (int j = 0; j < 3; ++j) {
            x0[i] += cm[3 * i + j] * d->centre[j];
        }
    }
    for (int i = 0; i < 9; ++i) {
        w[i] = k[i] / d->radius;
    }
    tf_model_set_map(model, x0, w);
    widen_to_reach(model, d, idx, m, x0, w);
    model->node_ids[0] = c->contact_id; /* tf_cases.contact_id */
    if (tf_family_spans(ctx, model, d->contact, idx, m) != 0) {
        tf_model_free(model);
        return NULL;
    }
    const uint32_t t = tf_terms(p);
    double *a = tf_family_design(model, d->contact, idx, m, p);
    double *y = malloc(m * 3 * sizeof *y), x[3 * TF_FAMILY_MAX_TERMS];
    int rc = -1;
    if (a != NULL && y != NULL) {
        for (size_t i = 0; i < m; ++i) {
            for (int j = 0; j < 3; ++j) {
                y[i + (size_t)j * m] = d->force[tf_family_case(idx, i)][j];
            }
        }
        rc = tf_family_lsq(ctx, a, m, t, y, 3, x);
    } else {
        tf_fail(ctx, "contact: out of memory");
    }
    if (rc == 0) {
        float *coef = tf_model_tables(model);
        for (int j = 0; j < 3; ++j) {
            for (uint32_t q = 0; q < t; ++q) {
                coef[(uint32_t)j * t + q] = (float)x[q + (uint32_t)j * t];
            }
        }
    }
    free(a);
    free(y);
    if (rc != 0) {
        tf_model_free(model);
        return NULL;
    }
    return model;
}

/* The degree by cross-validation, p >= 1 (p = 0 would be a constant force: no impedance). */
static int select_orders(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                         tf_family_result *r)
{
    return tf_family_select_by_degree(ctx, c, plan, 1, r);
}

static int candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg)
{
    return tf_family_degree_candidates(ctx, &tf_family_contact, c, plan, 1, take, arg);
}

const tf_family tf_family_contact = {
    .id = TFIT_FAMILY_CONTACT,
    .name = "contact",
    .kind = TF_FAMILY_INVERSE,
    .applicable = tf_family_always,
    .select = select_orders,
    .fit = fit,
    .candidates = candidates,
    .orders_text = tf_family_degree_text,
    .q31 = tf_q31_quantise,
    .f64_errors = tf_family_poly_f64_errors,
    .cost = tf_family_layout_cost,
};
