/*
 * eval_shim.h — a generated header's models, evaluated by libtfit in this
 * process (`tissuefit eval`): the header and its golden file are compiled
 * with the Python module's evaluator (python/tissuefit/tfit_shim.c, one
 * source for both) and the position-independent libtfit into a shared
 * object, which is loaded with dlopen.
 *
 * The compiler is $CC (default cc), split at blanks, with the project's
 * bit-exact flags (-std=c11 -O2 -ffp-contract=off).  The evaluator, tfit.h
 * and the library are found from the tool's own prefix, the folder above
 * the one holding the executable (/proc/self/exe):
 *
 *   PREFIX/share/tfit/tfit_shim.c
 *   PREFIX/include/tfit.h, tfit_q31.h
 *   PREFIX/lib/tfit/native-pic/libtfit.a
 *
 * `make install` puts them there; the build tree stages the same layout in
 * build/ beside build/bin/tissuefit.
 */
#ifndef TF_EVAL_SHIM_H
#define TF_EVAL_SHIM_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"

#define TF_EVAL_MAX_MODELS 64
#define TF_EVAL_NAME_MAX 128

/* A header's declarations, read from its text: the objects it names
 * without their tfit_ prefix, in the order declared. */
typedef struct tf_eval_decls {
    size_t n_models, n_models_q31, n_goldens, n_goldens_q31;
    char models[TF_EVAL_MAX_MODELS][TF_EVAL_NAME_MAX];
    char models_q31[TF_EVAL_MAX_MODELS][TF_EVAL_NAME_MAX];
    char goldens[TF_EVAL_MAX_MODELS][TF_EVAL_NAME_MAX];
    char goldens_q31[TF_EVAL_MAX_MODELS][TF_EVAL_NAME_MAX];
    int has_golden_file; /* NAME_golden.h is beside NAME.h and was asked for */
} tf_eval_decls;

/* The shim's entry points (tfit_shim.c). */
typedef struct tf_eval_shim {
    void *so;
    char dir[4096]; /* the temporary folder it was built in (removed at close) */
    int32_t (*model_info)(uint32_t i, uint32_t info[3]);
    int32_t (*eval)(uint32_t i, uint32_t n, const float *in, const float *s, float *out,
                    int32_t *status);
    int32_t (*eval_region)(uint32_t law, uint32_t surf, uint32_t n, const float *tip,
                           float *force, int32_t *status, float *surface,
                           int32_t *surface_status);
    float (*cut_golden_s)(uint32_t v);
    uint32_t (*goldens)(void);
    int32_t (*golden)(uint32_t j, uint32_t *model, uint32_t *n_vec, const uint32_t **in,
                      const int32_t **status, const uint32_t **out);
    int32_t (*model_q31_info)(uint32_t i, uint32_t info[3]);
    int32_t (*eval_q31)(uint32_t i, uint32_t n, const int32_t *in, int32_t *out,
                        int32_t *status);
    uint32_t (*goldens_q31)(void);
    int32_t (*golden_q31)(uint32_t j, uint32_t *model, uint32_t *n_vec, const int32_t **in,
                          const int32_t **status, const int32_t **out);
} tf_eval_shim;

/* Reads the declarations of header path (NAME.h) and, when `golden` is set
 * and it is there, of NAME_golden.h (compiled in only then: the golden
 * vectors of a large header take longer to compile than its models).
 * Returns 0, or -1 with a message naming the file (missing, unreadable, not
 * a generated header). */
int tf_eval_decls_read(tf_ctx *ctx, const char *path, int golden, tf_eval_decls *d);

/* Compiles and loads the evaluator of header path whose declarations are d.
 * Returns 0, or -1 with the message (the compiler's output included);
 * nothing is left behind on failure. */
int tf_eval_shim_open(tf_ctx *ctx, tf_eval_shim *sh, const char *path, const tf_eval_decls *d);

/* Unloads the object and removes its temporary folder. */
void tf_eval_shim_close(tf_eval_shim *sh);

#endif /* TF_EVAL_SHIM_H */
