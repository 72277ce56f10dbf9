/*
 * region_ref.h — the host's reference evaluator of the region models
 * (docs/header-format.md §5.10-§5.12): the contact law over a region, the
 * surface for the current contact, and the two-instrument forms.
 *
 * Written from the header-format text, not from target/src: every float
 * operation is done in double and rounded to float at once (exact binary32
 * arithmetic, ref_eval.h), every selection is an ordinary branch.  The
 * golden vectors' and the self-tests' expected bits of region models come
 * from here.
 */
#ifndef TF_REGION_REF_H
#define TF_REGION_REF_H

#include <stddef.h>
#include <stdint.h>

#include "model/model.h"

/* A region law's state (TFIT_REGION_STATE_WORDS floats) after
 * tfit_region_reset: proxy (0, 0), no contact. */
void tf_region_ref_reset(float *state);

/* One tick of a region law (§5.10), as tfit_region_force: tip (mm, scene
 * frame) -> force (N, scene frame); updates state. */
tfit_status tf_region_ref_force(const tf_model *law, float *state, const float tip[3],
                                float force[3]);

/* The surface (§5.11), as tfit_region_surface: out[3 n_out]. */
tfit_status tf_region_ref_surface(const tf_model *surf, const float *state, const float force[3],
                                  float *out);

/* Two instruments (§5.12), as tfit_region_pair and tfit_region_surface_pair:
 * state2 two states one after the other, tip2 and force2 two 3-vectors. */
tfit_status tf_region_ref_pair(const tf_model *law, const tf_model *surf, float *state2,
                               const float tip2[6], float force2[6]);
tfit_status tf_region_ref_surface_pair(const tf_model *surf, const float *state2,
                                       const float force2[6], float *out);

/* The proxy state of a surface golden vector v (§7): the grid fractions
 * TFIT_CUT_GOLDEN_S_BITS[v mod 16] and [(7 v + 3) mod 16], in contact. */
void tf_region_ref_golden_state(const tf_model *surf, uint32_t v, float state[3]);

#endif /* TF_REGION_REF_H */
