/*
 * blas_pin.h — reproducible floating point from OpenBLAS.
 *
 * OpenBLAS chooses its kernels for the CPU it finds (Haswell, SkylakeX, ...)
 * and splits work over threads; both change the last bits of LAPACK and
 * CHOLMOD results (measured: dgels on a 400x35 system gives different bits
 * for the Haswell and SkylakeX kernels, and for 1 and 2 threads).  Generated
 * headers must be byte-identical wherever they are regenerated, so the tool
 * pins one kernel family and one BLAS thread (our own parallel loops are
 * deterministic by construction).  OpenBLAS reads these settings when it is
 * loaded, so the process re-executes itself once with them set.
 */
#ifndef TF_BLAS_PIN_H
#define TF_BLAS_PIN_H

/* Kernel family pinned on x86-64 CPUs with AVX2 and FMA; "Prescott"
 * (SSE3) otherwise, which gives other bits: say so when it happens. */
#define TF_BLAS_CORETYPE "Haswell"
#define TF_BLAS_CORETYPE_FALLBACK "Prescott"

/* Call first in main().  Returns only when the environment is pinned (after
 * a re-exec if needed); on failure to re-exec, warns and continues. */
void tf_blas_pin(char **argv);

/* The kernel family the tool pins on this CPU (TF_BLAS_CORETYPE or the
 * fallback), or NULL on other architectures (one family per build).  The
 * Python module (host/api/) compares it with the family OpenBLAS loaded. */
const char *tf_blas_wanted_coretype(void);

/* The kernel family in use, for banners and reports. */
const char *tf_blas_coretype(void);

#endif /* TF_BLAS_PIN_H */
