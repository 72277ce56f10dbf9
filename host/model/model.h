/*
 * model.h — a fitted model held in memory by the host, in exactly the table
 * layout the target evaluates (docs/header-format.md §3), plus the metadata
 * the generated header reports.
 */
#ifndef TF_MODEL_H
#define TF_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "cost/cycles.h"
#include "tfit.h"

#define TF_NAME_MAX 64

typedef struct tf_model {
    char name[TF_NAME_MAX]; /* C identifier suffix, lower case: "block48_forward" */
    tfit_family family;
    uint32_t n_out;
    uint32_t n_dims;
    uint32_t dims[TFIT_ZHOU2017_DIMS];
    uint32_t n_coef;
    float *coef;        /* owned; first TFIT_INPUT_MAP_FLOATS are x0, W */
    uint32_t *node_ids; /* owned; n_out scene node numbers */

    /* Metadata reported in the header.  NAN means "not measured". */
    double envelope_radius;  /* ball radius in input units, 0 when the envelope is an ellipsoid */
    double heldout_max;      /* held-out max abs error, output units (mm or N) */
    double heldout_rms;      /* held-out RMS error, output units */
    double heldout_rel_max;  /* held-out max relative error (contact models) */
    uint32_t heldout_cases;  /* number of held-out load cases behind the numbers */
    double heldout_q31_max;  /* prony: the Q31 form's held-out max abs error (q31-format.md §8) */
    /* Contact models (passivity.h): smallest eigenvalue of the symmetric
     * stiffness and largest ||J||_2 over the envelope, N/mm. */
    double stiffness_min, stiffness_max;
    uint32_t passivity_samples; /* 0: not checked */
    /* The solve's own error against a reference of the physics
     * (fitting/discretisation.h), output units; NAN: not measured. */
    double discretisation_max;
    char discretisation_note[768]; /* what it was measured against */
    /* What else the fit states of the model, as lines of the header's banner
     * ("": nothing; a contact region's sites, spacing and why, rank, ...). */
    char fit_note[768];
} tf_model;

/* Floating-point operation counts of one evaluation (docs/header-format.md §6). */
typedef struct tf_opcount {
    uint64_t add; /* additions and subtractions */
    uint64_t mul;
    uint64_t div;
} tf_opcount;

/* Terms of the total-degree-p basis in 3 variables. */
uint32_t tf_terms(uint32_t p);

/* coef[] length for a family, its dims and n_out, by its form
 * (model/forms/form.h); 0 if invalid. */
uint32_t tf_model_ncoef(tfit_family family, uint32_t n_out, const uint32_t *dims, uint32_t n_dims);

/* Allocates a model with zeroed tables and identity input map, metadata NAN.
 * Returns NULL (and a message in ctx->err) when the shape is invalid. */
tf_model *tf_model_new(tf_ctx *ctx, const char *name, tfit_family family, uint32_t n_out,
                       const uint32_t *dims, uint32_t n_dims);
void tf_model_free(tf_model *m);
tf_model *tf_model_clone(const tf_model *m);

/* Input map: ball of radius r around centre (W = I / r). */
void tf_model_set_ball(tf_model *m, const double centre[3], double radius);
/* Input map: general ellipsoid |W (x - x0)| <= 1. */
void tf_model_set_map(tf_model *m, const double x0[3], const double w[9]);

/* The family tables after the input map. */
float *tf_model_tables(tf_model *m);

/* CRC-32 (zlib) in the target's serialisation. */
uint32_t tf_model_crc32(const tf_model *m);

/* One step of that CRC: crc updated with w as four little-endian bytes
 * (start from 0, no final xor: zlib's convention). */
uint32_t tf_crc32_u32(uint32_t crc, uint32_t w);

/* Checks what tfit_model_check() will check on the device (sizes, finite
 * coefficients, no reachable overflow), with a message naming the table and
 * index at fault.  Returns 0 when the model is emittable. */
int tf_model_validate(tf_ctx *ctx, const tf_model *m);

/* Operation count of one evaluation, from its form's formulas. */
tf_opcount tf_model_ops(const tf_model *m);

/* The instructions one call of the compiled evaluator executes on a core,
 * by class (its form's blocks: the prediction of what QEMU traces), and
 * the cycles of that mix (tfit_displacements, tfit_contact_force,
 * tfit_displacements_cut or a stateful step, the call from C included). */
void tf_model_insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix);
tf_cycles tf_model_cycles(const tf_model *m, tf_core core);

/* Bytes of the model's const tables (coef, dims, node ids), without the
 * descriptor struct whose size depends on the target's pointer width. */
uint32_t tf_model_table_bytes(const tf_model *m);

#endif /* TF_MODEL_H */
