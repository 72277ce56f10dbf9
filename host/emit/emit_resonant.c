/*
 * emit_resonant.c — see emit_resonant.h.
 */
#include "emit/emit_resonant.h"

#include <math.h>

#include "emit/emit_prony.h"
#include "model/resonant.h"

#define TWO_PI 6.28318530717958647692

void tf_emit_resonant_banner(FILE *f, const tf_model *m)
{
    if (m->family != TFIT_FAMILY_RESONANT) {
        return;
    }
    fprintf(f,
            " *       stateful: tick %u ns, state %u floats (tfit_resonant_reset, "
            "tfit_resonant_step); %u damped mode%s:",
            m->dims[3], TFIT_RESONANT_STATE_WORDS(m->dims[2]), m->dims[2],
            m->dims[2] == 1 ? "" : "s");
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        double omega, zeta, w[3];
        tf_resonant_get_mode(m, k, &omega, &zeta, w);
        fprintf(f, " %.4g Hz zeta %.3g w (%.3g %.3g %.3g)%s", omega / TWO_PI, zeta, w[0], w[1],
                w[2], k + 1 < m->dims[2] ? ";" : "");
    }
    fprintf(f, "\n");
    if (!isnan(m->heldout_rel_max)) {
        fprintf(f,
                " *       held-out cases are force histories stepped from rest: largest error "
                "%.3g %% of the largest displacement\n",
                100 * m->heldout_rel_max);
    }
}

void tf_emit_resonant_macros(FILE *f, const tf_model *m, const char *p)
{
    if (m->family != TFIT_FAMILY_RESONANT) {
        return;
    }
    fprintf(f, "#define %s_MODES %u\n", p, m->dims[2]);
    fprintf(f, "#define %s_STATE_WORDS %uu /* float state[]: tfit_resonant_reset, _step */\n", p,
            TFIT_RESONANT_STATE_WORDS(m->dims[2]));
    tf_emit_tick_macros(f, m, p, "tfit_resonant_step");
}

void tf_emit_resonant_modes(FILE *f, const tf_model *m)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0; k < m->dims[2]; ++k, pt += 7) {
        double omega, zeta, w[3];
        tf_resonant_get_mode(m, k, &omega, &zeta, w);
        fprintf(f,
                "    /* resonant mode %u: F (2 x 2, row-major), weights x y z (%.6g Hz, zeta "
                "%.6g) */\n",
                k, omega / TWO_PI, zeta);
        fprintf(f, "    %af, %af, %af, %af, %af, %af, %af,\n", (double)pt[0], (double)pt[1],
                (double)pt[2], (double)pt[3], (double)pt[4], (double)pt[5], (double)pt[6]);
    }
}
