/*
 * tfit_shim.c — the models of one generated header, evaluated by libtfit
 * over arrays, for the Python module (header.py compiles this file with the
 * header into a shared object and loads it with ctypes).
 *
 * Compiled with the project's bit-exact flags (-std=c11 -O2
 * -ffp-contract=off) and
 *   -DTF_SHIM_HEADER_FILE='"NAME.h"' [-DTF_SHIM_GOLDEN_FILE='"NAME_golden.h"']
 *   -DTFIT_NAME_IMPLEMENTATION -DTF_SHIM_LIST_FILE='"list.h"'
 * where list.h names the header's objects, one X-macro line each:
 * TF_SHIM_MODEL(tfit_x), TF_SHIM_MODEL_Q31(tfit_x_q31), TF_SHIM_GOLDEN(...),
 * TF_SHIM_GOLDEN_Q31(...).  Each entry point evaluates a model as the
 * library's golden runner does (tfit_golden.c, tfit_q31_golden.c): the
 * contact family through tfit_contact_force, a cut model at its cut
 * progress, a prony or resonant model as one tick sequence from rest, a
 * region law as one tick sequence of tool-tip positions from a reset state
 * (tf_shim_eval_region adds the surface of its region at every tick).
 *
 * Two programs compile this one file: the Python module (header.py, into a
 * shared object it loads with ctypes) and `tissuefit eval`
 * (host/cli/cmd_eval.c, which loads the same shared object with dlopen), so
 * both evaluate a header through the same calls of libtfit.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include TF_SHIM_HEADER_FILE
#ifdef TF_SHIM_GOLDEN_FILE
#include TF_SHIM_GOLDEN_FILE
#endif
#include "tfit_q31.h"

#define TF_SHIM_MODEL(obj)
#define TF_SHIM_MODEL_Q31(obj)
#define TF_SHIM_GOLDEN(obj)
#define TF_SHIM_GOLDEN_Q31(obj)

/* Each list ends with a NULL entry: a header may have no Q31 model, and
 * a header without its golden file no golden vectors. */
#undef TF_SHIM_MODEL
#define TF_SHIM_MODEL(obj) {&obj, #obj},
static const struct {
    const tfit_model *m;
    const char *name;
} models[] = {
#include TF_SHIM_LIST_FILE
    {NULL, NULL}};
#undef TF_SHIM_MODEL
#define TF_SHIM_MODEL(obj)

#undef TF_SHIM_MODEL_Q31
#define TF_SHIM_MODEL_Q31(obj) {&obj, #obj},
static const struct {
    const tfit_model_q31 *m;
    const char *name;
} models_q31[] = {
#include TF_SHIM_LIST_FILE
    {NULL, NULL}};
#undef TF_SHIM_MODEL_Q31
#define TF_SHIM_MODEL_Q31(obj)

#undef TF_SHIM_GOLDEN
#define TF_SHIM_GOLDEN(obj) &obj,
static const tfit_golden *const goldens[] = {
#include TF_SHIM_LIST_FILE
    NULL};
#undef TF_SHIM_GOLDEN
#define TF_SHIM_GOLDEN(obj)

#undef TF_SHIM_GOLDEN_Q31
#define TF_SHIM_GOLDEN_Q31(obj) &obj,
static const tfit_golden_q31 *const goldens_q31[] = {
#include TF_SHIM_LIST_FILE
    NULL};

#define COUNT(a) ((uint32_t)(sizeof a / sizeof a[0]) - 1u)

/* The prototypes of the entry points (ctypes reads the symbols). */
uint32_t tf_shim_models(void);
const char *tf_shim_model_name(uint32_t i);
int32_t tf_shim_model_info(uint32_t i, uint32_t info[3]);
int32_t tf_shim_eval(uint32_t i, uint32_t n, const float *in, const float *s, float *out,
                     int32_t *status);
int32_t tf_shim_eval_region(uint32_t law, uint32_t surf, uint32_t n, const float *tip,
                            float *force, int32_t *status, float *surface,
                            int32_t *surface_status);
float tf_shim_cut_golden_s(uint32_t v);
uint32_t tf_shim_goldens(void);
int32_t tf_shim_golden(uint32_t j, uint32_t *model, uint32_t *n_vec, const uint32_t **in,
                       const int32_t **status, const uint32_t **out);
uint32_t tf_shim_golden_run(uint32_t j);
uint32_t tf_shim_models_q31(void);
const char *tf_shim_model_q31_name(uint32_t i);
int32_t tf_shim_model_q31_info(uint32_t i, uint32_t info[3]);
int32_t tf_shim_eval_q31(uint32_t i, uint32_t n, const int32_t *in, int32_t *out,
                         int32_t *status);
uint32_t tf_shim_goldens_q31(void);
int32_t tf_shim_golden_q31(uint32_t j, uint32_t *model, uint32_t *n_vec, const int32_t **in,
                           const int32_t **status, const int32_t **out);
uint32_t tf_shim_golden_run_q31(uint32_t j);

/* ---- float models ----------------------------------------------------- */

uint32_t tf_shim_models(void)
{
    return COUNT(models);
}

const char *tf_shim_model_name(uint32_t i)
{
    return i < COUNT(models) ? models[i].name : NULL;
}

/* info: family, n_out, output points per input (1 for contact); returns
 * tfit_model_check's status, or TFIT_ERR_ARG for an index beyond. */
int32_t tf_shim_model_info(uint32_t i, uint32_t info[3])
{
    if (i >= COUNT(models)) {
        return TFIT_ERR_ARG;
    }
    info[0] = models[i].m->family;
    info[1] = models[i].m->n_out;
    info[2] = models[i].m->n_out;
    return tfit_model_check(models[i].m);
}

/* n inputs in[3 n] (forces in N, contact displacements in mm for the
 * contact family, tool-tip positions in mm for a region law; s[n] the cut
 * progress of a cut model) into out[3 n_out n] and status[n] (a region
 * law's n_out is 1: its outputs are the forces).  A region surface's input
 * k is a force (N) at the proxy of golden vector k, as tfit_golden_run
 * places it (tfit.h: fractions of the grid from TFIT_CUT_GOLDEN_S_BITS; its
 * law's proxies: tf_shim_eval_region).  Returns 0, or -1 for a bad index or
 * a cut model without s. */
int32_t tf_shim_eval(uint32_t i, uint32_t n, const float *in, const float *s, float *out,
                     int32_t *status)
{
    if (i >= COUNT(models)) {
        return -1;
    }
    const tfit_model *m = models[i].m;
    const uint32_t w = 3u * m->n_out;
    float state[TFIT_RESONANT_MAX_STATE > TFIT_PRONY_MAX_STATE ? TFIT_RESONANT_MAX_STATE
                                                                 : TFIT_PRONY_MAX_STATE];
    if (m->family == (uint32_t)TFIT_FAMILY_CUT && s == NULL) {
        return -1;
    }
    if (m->family == (uint32_t)TFIT_FAMILY_PRONY) {
        (void)tfit_prony_reset(m, state);
    } else if (m->family == (uint32_t)TFIT_FAMILY_RESONANT) {
        (void)tfit_resonant_reset(m, state);
    } else if (m->family == (uint32_t)TFIT_FAMILY_REGION) {
        (void)tfit_region_reset(m, state);
    }
    for (uint32_t k = 0u; k < n; ++k) {
        const float *x = in + 3u * k;
        float *y = out + (size_t)w * k;
        switch (m->family) {
        case TFIT_FAMILY_PRONY:
            status[k] = tfit_prony_step(m, state, x, y);
            break;
        case TFIT_FAMILY_RESONANT:
            status[k] = tfit_resonant_step(m, state, x, y);
            break;
        case TFIT_FAMILY_CUT:
            status[k] = tfit_displacements_cut(m, x, s[k], y);
            break;
        case TFIT_FAMILY_CONTACT:
            status[k] = tfit_contact_force(m, x, y);
            break;
        case TFIT_FAMILY_REGION:
            status[k] = tfit_region_force(m, state, x, y);
            break;
        case TFIT_FAMILY_REGION_SURFACE: {
            const float proxy[3] = {tf_shim_cut_golden_s(k) * (float)(m->dims[0] - 1u),
                                    tf_shim_cut_golden_s(7u * k + 3u) * (float)(m->dims[1] - 1u),
                                    1.0f};
            status[k] = tfit_region_surface(m, proxy, x, y);
            break;
        }
        default:
            status[k] = tfit_displacements(m, x, y);
            break;
        }
    }
    return 0;
}

/* The firmware's loop of one instrument (tfit.h, region models): region law
 * `law` stepped over the n tool-tip positions tip[3 n] from a reset state,
 * its forces into force[3 n] and statuses into status[n]; when surf is a
 * region surface's index (not UINT32_MAX), the surface under each tick's
 * force at that tick's proxy into surface[3 n_out n] and its statuses into
 * surface_status[n].  Returns 0, or -1 for an index beyond or a model of
 * another family. */
int32_t tf_shim_eval_region(uint32_t law, uint32_t surf, uint32_t n, const float *tip,
                            float *force, int32_t *status, float *surface,
                            int32_t *surface_status)
{
    const int with_surface = surf != UINT32_MAX;
    if (law >= COUNT(models) || models[law].m->family != (uint32_t)TFIT_FAMILY_REGION ||
        (with_surface && (surf >= COUNT(models) || surface == NULL || surface_status == NULL ||
                          models[surf].m->family != (uint32_t)TFIT_FAMILY_REGION_SURFACE))) {
        return -1;
    }
    float state[TFIT_REGION_STATE_WORDS];
    (void)tfit_region_reset(models[law].m, state);
    for (uint32_t k = 0u; k < n; ++k) {
        status[k] = tfit_region_force(models[law].m, state, tip + 3u * k, force + 3u * k);
        if (with_surface) {
            const tfit_model *sm = models[surf].m;
            surface_status[k] = tfit_region_surface(sm, state, force + 3u * k,
                                                    surface + (size_t)3u * sm->n_out * k);
        }
    }
    return 0;
}

/* The cut progress of cut golden vector v (tfit.h). */
float tf_shim_cut_golden_s(uint32_t v)
{
    static const uint32_t bits[16] = TFIT_CUT_GOLDEN_S_BITS;
    union {
        uint32_t u;
        float f;
    } b = {bits[v & 15u]};
    return b.f;
}

uint32_t tf_shim_goldens(void)
{
    return COUNT(goldens);
}

/* Golden set j: its model's index in the list above and its arrays.
 * Returns 0, or -1 for an index beyond or a model not in the list. */
int32_t tf_shim_golden(uint32_t j, uint32_t *model, uint32_t *n_vec, const uint32_t **in,
                       const int32_t **status, const uint32_t **out)
{
    if (j >= COUNT(goldens)) {
        return -1;
    }
    const tfit_golden *g = goldens[j];
    for (uint32_t i = 0u; i < COUNT(models); ++i) {
        if (models[i].m == g->model) {
            *model = i;
            *n_vec = g->n_vec;
            *in = g->in;
            *status = g->status;
            *out = g->out;
            return 0;
        }
    }
    return -1;
}

/* The library's own count of mismatching words for set j (tfit_golden_run). */
uint32_t tf_shim_golden_run(uint32_t j)
{
    float *scratch = j < COUNT(goldens) ? malloc(3u * goldens[j]->model->n_out * sizeof *scratch)
                                        : NULL;
    uint32_t bad = scratch != NULL ? tfit_golden_run(goldens[j], scratch) : UINT32_MAX;
    free(scratch);
    return bad;
}

/* ---- Q31 models (tfit_q31.h): the same over int32 words ------------------ */

uint32_t tf_shim_models_q31(void)
{
    return COUNT(models_q31);
}

const char *tf_shim_model_q31_name(uint32_t i)
{
    return i < COUNT(models_q31) ? models_q31[i].name : NULL;
}

int32_t tf_shim_model_q31_info(uint32_t i, uint32_t info[3])
{
    if (i >= COUNT(models_q31)) {
        return TFIT_ERR_ARG;
    }
    info[0] = models_q31[i].m->family;
    info[1] = models_q31[i].m->n_out;
    info[2] = models_q31[i].m->n_out;
    return tfit_model_check_q31(models_q31[i].m);
}

/* As tf_shim_eval, in the header's Q31 scalings (its _Q31_IN_EXP and
 * _Q31_OUT_EXP); a prony model's inputs are one tick sequence from rest. */
int32_t tf_shim_eval_q31(uint32_t i, uint32_t n, const int32_t *in, int32_t *out, int32_t *status)
{
    if (i >= COUNT(models_q31)) {
        return -1;
    }
    const tfit_model_q31 *m = models_q31[i].m;
    const uint32_t w = 3u * m->n_out;
    int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
    if (m->family == (uint32_t)TFIT_FAMILY_PRONY) {
        (void)tfit_prony_reset_q31(m, state);
    }
    for (uint32_t k = 0u; k < n; ++k) {
        const int32_t *x = in + 3u * k;
        int32_t *y = out + (size_t)w * k;
        status[k] = m->family == (uint32_t)TFIT_FAMILY_PRONY     ? tfit_prony_step_q31(m, state, x, y)
                    : m->family == (uint32_t)TFIT_FAMILY_CONTACT ? tfit_contact_force_q31(m, x, y)
                                                                 : tfit_displacements_q31(m, x, y);
    }
    return 0;
}

uint32_t tf_shim_goldens_q31(void)
{
    return COUNT(goldens_q31);
}

int32_t tf_shim_golden_q31(uint32_t j, uint32_t *model, uint32_t *n_vec, const int32_t **in,
                           const int32_t **status, const int32_t **out)
{
    if (j >= COUNT(goldens_q31)) {
        return -1;
    }
    const tfit_golden_q31 *g = goldens_q31[j];
    for (uint32_t i = 0u; i < COUNT(models_q31); ++i) {
        if (models_q31[i].m == g->model) {
            *model = i;
            *n_vec = g->n_vec;
            *in = g->in;
            *status = g->status;
            *out = g->out;
            return 0;
        }
    }
    return -1;
}

uint32_t tf_shim_golden_run_q31(uint32_t j)
{
    int32_t *scratch = j < COUNT(goldens_q31)
                           ? malloc(3u * goldens_q31[j]->model->n_out * sizeof *scratch)
                           : NULL;
    uint32_t bad = scratch != NULL ? tfit_golden_run_q31(goldens_q31[j], scratch) : UINT32_MAX;
    free(scratch);
    return bad;
}
