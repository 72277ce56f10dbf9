/*
 * emit_prony.c — see emit_prony.h.
 */
#include "emit/emit_prony.h"

#include <math.h>

#include "model/prony.h"

/* The term's time constant (s) as the device realises it, and its weight
 * in the normalised creep function (prony.h). */
static void term(const tf_model *m, uint32_t k, double *tau, double *weight)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + 2 * k;
    const double gain = tf_prony_hold_gain(pt[0]);
    *tau = tf_prony_realised_tau(tf_prony_tick(m), pt[0]);
    *weight = gain > 0 ? (double)pt[1] / gain : 0.0;
}

void tf_emit_prony_banner(FILE *f, const tf_model *m)
{
    if (m->family != TFIT_FAMILY_PRONY) {
        return;
    }
    fprintf(f,
            " *       stateful: tick %u ns, state %u floats (tfit_prony_reset, tfit_prony_step);"
            " creep J(t)/J(inf) = 1",
            m->dims[3], TFIT_PRONY_STATE_WORDS(m->dims[2]));
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        double tau, w;
        term(m, k, &tau, &w);
        fprintf(f, " - %.4g exp(-t/%.4g s)", w, tau);
    }
    fprintf(f, "\n");
    if (!isnan(m->heldout_rel_max)) {
        fprintf(f,
                " *       held-out cases are force histories stepped from rest: largest error "
                "%.3g %% of the largest displacement\n",
                100 * m->heldout_rel_max);
    }
}

void tf_emit_prony_macros(FILE *f, const tf_model *m, const char *p)
{
    if (m->family != TFIT_FAMILY_PRONY) {
        return;
    }
    fprintf(f, "#define %s_TERMS %u\n", p, m->dims[2]);
    fprintf(f, "#define %s_STATE_WORDS %uu /* float state[]: tfit_prony_reset, _step */\n", p,
            TFIT_PRONY_STATE_WORDS(m->dims[2]));
    tf_emit_tick_macros(f, m, p, "tfit_prony_step");
}

void tf_emit_tick_macros(FILE *f, const tf_model *m, const char *p, const char *step)
{
    const uint32_t ns = m->dims[3];
    fprintf(f, "#define %s_TICK_NS %uu /* the model's tick: call %s at %.9g Hz */\n", p, ns, step,
            1e9 / ns);
    /* The firmware states its own tick as TFIT_TICK_NS or TFIT_TICK_US: a
     * model fitted for another one must not build (the discrete update is
     * exact for this period only). */
    fprintf(f,
            "#if defined(TFIT_TICK_NS) && (TFIT_TICK_NS) != %u\n"
            "#error \"%s: fitted for a %u ns tick, the firmware's TFIT_TICK_NS differs: refit "
            "with that tick\"\n#endif\n",
            ns, m->name, ns);
    fprintf(f,
            "#if defined(TFIT_TICK_US) && (TFIT_TICK_US) * 1000 != %u\n"
            "#error \"%s: fitted for a %u ns tick, the firmware's TFIT_TICK_US differs: refit "
            "with that tick\"\n#endif\n",
            ns, m->name, ns);
}

void tf_emit_prony_terms(FILE *f, const tf_model *m)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        double tau, w;
        char note[128];
        term(m, k, &tau, &w);
        snprintf(note, sizeof note, "prony term %u: decay a, gain D (tau %.6g s, weight %.6g)", k,
                 tau, w);
        fprintf(f, "    /* %s */\n    %af, %af,\n", note, (double)pt[2 * k], (double)pt[2 * k + 1]);
    }
}
