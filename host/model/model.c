/*
 * model.c — host-side model tables: allocation, input map, CRC, and the
 * sizes, validation and costs their form (model/forms/) gives.  The sizes
 * and bounds are written from docs/header-format.md, independently of
 * target/src, so that the tests compare two implementations of one
 * specification.
 */
#include "model/model.h"

#include "model/forms/form.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

/* One bit of margin under the target's limits (2^64, 2^56): the target
 * sums in float, the host in double. */
#define X0_LIMIT 0x1p63
#define W_LIMIT 0x1p55

uint32_t tf_terms(uint32_t p)
{
    return (p + 1) * (p + 2) * (p + 3) / 6;
}

uint32_t tf_model_ncoef(tfit_family family, uint32_t n_out, const uint32_t *dims, uint32_t n_dims)
{
    const tf_form *f = tf_form_of(family);
    if (f == NULL || n_dims != f->n_dims || n_out == 0 || n_out > (1u << 20)) {
        return 0;
    }
    const uint64_t n = f->coefs(f, n_out, dims);
    return n > UINT32_MAX ? 0 : (uint32_t)n;
}

tf_model *tf_model_new(tf_ctx *ctx, const char *name, tfit_family family, uint32_t n_out,
                       const uint32_t *dims, uint32_t n_dims)
{
    uint32_t n_coef = tf_model_ncoef(family, n_out, dims, n_dims);
    if (n_coef == 0) {
        tf_fail(ctx, "model '%s': invalid shape for family %d (n_out %u, %u dims)", name,
                (int)family, n_out, n_dims);
        return NULL;
    }
    if (strlen(name) >= TF_NAME_MAX) {
        tf_fail(ctx, "model name '%s' longer than %d characters", name, TF_NAME_MAX - 1);
        return NULL;
    }
    tf_model *m = calloc(1, sizeof *m);
    float *coef = calloc(n_coef, sizeof *coef);
    uint32_t *ids = calloc(n_out, sizeof *ids);
    if (m == NULL || coef == NULL || ids == NULL) {
        free(m);
        free(coef);
        free(ids);
        tf_fail(ctx, "out of memory for model '%s' (%u coefficients)", name, n_coef);
        return NULL;
    }
    snprintf(m->name, sizeof m->name, "%s", name);
    m->family = family;
    m->n_out = n_out;
    m->n_dims = n_dims;
    memcpy(m->dims, dims, n_dims * sizeof *dims);
    m->n_coef = n_coef;
    m->coef = coef;
    m->node_ids = ids;
    m->envelope_radius = 0.0;
    m->heldout_max = m->heldout_rms = m->heldout_rel_max = m->heldout_q31_max = NAN;
    m->stiffness_min = m->stiffness_max = m->discretisation_max = NAN;
    const double zero[3] = {0, 0, 0};
    tf_model_set_ball(m, zero, 1.0);
    return m;
}

void tf_model_free(tf_model *m)
{
    if (m != NULL) {
        free(m->coef);
        free(m->node_ids);
        free(m);
    }
}

tf_model *tf_model_clone(const tf_model *m)
{
    tf_model *c = malloc(sizeof *c);
    float *coef = malloc(m->n_coef * sizeof *coef);
    uint32_t *ids = malloc(m->n_out * sizeof *ids);
    if (c == NULL || coef == NULL || ids == NULL) {
        free(c);
        free(coef);
        free(ids);
        return NULL;
    }
    *c = *m;
    memcpy(coef, m->coef, m->n_coef * sizeof *coef);
    memcpy(ids, m->node_ids, m->n_out * sizeof *ids);
    c->coef = coef;
    c->node_ids = ids;
    return c;
}

void tf_model_set_map(tf_model *m, const double x0[3], const double w[9])
{
    for (int i = 0; i < 3; ++i) {
        m->coef[i] = (float)x0[i];
    }
    for (int i = 0; i < 9; ++i) {
        m->coef[3 + i] = (float)w[i];
    }
    m->envelope_radius = 0.0;
}

void tf_model_set_ball(tf_model *m, const double centre[3], double radius)
{
    const double w[9] = {1 / radius, 0, 0, 0, 1 / radius, 0, 0, 0, 1 / radius};
    tf_model_set_map(m, centre, w);
    m->envelope_radius = radius;
}

float *tf_model_tables(tf_model *m)
{
    return m->coef + TFIT_INPUT_MAP_FLOATS;
}

uint32_t tf_crc32_u32(uint32_t crc, uint32_t w)
{
    const unsigned char b[4] = {(unsigned char)w, (unsigned char)(w >> 8), (unsigned char)(w >> 16),
                                (unsigned char)(w >> 24)};
    return (uint32_t)crc32(crc, b, 4);
}

uint32_t tf_model_crc32(const tf_model *m)
{
    uint32_t crc = (uint32_t)crc32(0L, Z_NULL, 0);
    crc = tf_crc32_u32(crc, TFIT_API_VERSION);
    crc = tf_crc32_u32(crc, (uint32_t)m->family);
    crc = tf_crc32_u32(crc, m->n_out);
    crc = tf_crc32_u32(crc, m->n_dims);
    crc = tf_crc32_u32(crc, m->n_coef);
    for (uint32_t i = 0; i < m->n_dims; ++i) {
        crc = tf_crc32_u32(crc, m->dims[i]);
    }
    for (uint32_t i = 0; i < m->n_coef; ++i) {
        uint32_t bits;
        memcpy(&bits, &m->coef[i], sizeof bits);
        crc = tf_crc32_u32(crc, bits);
    }
    for (uint32_t i = 0; i < m->n_out; ++i) {
        crc = tf_crc32_u32(crc, m->node_ids[i]);
    }
    return crc;
}

int tf_model_validate(tf_ctx *ctx, const tf_model *m)
{
    if (tf_model_ncoef(m->family, m->n_out, m->dims, m->n_dims) != m->n_coef) {
        tf_fail(ctx, "model '%s': table size %u does not match its family and orders", m->name,
                m->n_coef);
        return 1;
    }
    for (int i = 0; i < TFIT_INPUT_MAP_FLOATS; ++i) {
        double v = fabs((double)m->coef[i]);
        if (!(v <= (i < 3 ? X0_LIMIT : W_LIMIT))) {
            tf_fail(ctx, "model '%s': input map entry %d is %g (envelope degenerate?)", m->name, i,
                    (double)m->coef[i]);
            return 1;
        }
    }
    for (uint32_t i = 0; i < m->n_coef; ++i) {
        if (!isfinite(m->coef[i])) {
            tf_fail(ctx, "model '%s': coefficient %u is not finite", m->name, i);
            return 1;
        }
    }
    return tf_form_of(m->family)->bounds(ctx, m);
}

tf_opcount tf_model_ops(const tf_model *m)
{
    tf_opcount ops = {0, 0, 0};
    tf_form_of(m->family)->ops(m, &ops);
    return ops;
}

void tf_model_insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    memset(mix, 0, sizeof *mix);
    tf_form_of(m->family)->insn_mix(m, core, mix);
}

tf_cycles tf_model_cycles(const tf_model *m, tf_core core)
{
    tf_insn_mix mix;
    tf_model_insn_mix(m, core, &mix);
    return tf_cycles_of_mix(&mix, core);
}

/* The same for every form: the coefficients, dims and node ids. */
uint32_t tf_model_table_bytes(const tf_model *m)
{
    return 4 * (m->n_coef + m->n_dims + m->n_out);
}
