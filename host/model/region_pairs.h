/*
 * region_pairs.h — the two-instrument vectors of an affine region (a law
 * of degree P = 2, a surface of degree p = 1 with site modes;
 * docs/header-format.md §5.12, §7), computed by the host reference
 * evaluator (region_ref.h): what a region header's golden file and the
 * generated-model tests check the target's tfit_region_pair and
 * tfit_region_surface_pair against.
 *
 * Pair ticks: both proxies from reset states; the first instrument's tips
 * are the law's golden design (model/golden.h), the second's the design of
 * the next seed shifted by 7 ticks (so that they press, slide and lift at
 * other times).  Surface pairs: the surface's golden states v and v + 5
 * with its golden forces v and v + 11.
 */
#ifndef TF_REGION_PAIRS_H
#define TF_REGION_PAIRS_H

#include <stddef.h>
#include <stdint.h>

#include "model/golden.h"
#include "model/model.h"

typedef struct tf_region_pairs {
    size_t n;                          /* pair ticks (0 unless the region is affine) */
    float tip[TF_GOLDEN_MAX][6];
    int32_t status[TF_GOLDEN_MAX];
    float force[TF_GOLDEN_MAX][6];
    float state[TF_GOLDEN_MAX][6];     /* the two states after each tick */
    size_t ns;                         /* surface pairs (0 unless p = 1) */
    float sstate[TF_GOLDEN_MAX][6];
    float sforce[TF_GOLDEN_MAX][6];
    int32_t sstatus[TF_GOLDEN_MAX];
    float *sout;                       /* ns x 3 n_out */
} tf_region_pairs;

/* Whether law and surf are the two-instrument forms (P = 2; p = 1 with
 * site modes). */
int tf_region_pairs_affine(const tf_model *law, const tf_model *surf);

/* The vectors of law and surf from golden seed `seed`.  Returns 0, or -1
 * (out of memory). */
int tf_region_pairs_design(const tf_model *law, const tf_model *surf, uint64_t seed,
                           tf_region_pairs *p);
void tf_region_pairs_free(tf_region_pairs *p);

#endif /* TF_REGION_PAIRS_H */
