/*
 * qemu_region.c — runs the region cases of a generated header
 * (gen_region.c header) on the device (QEMU boards, semihosting): per case
 * the law's and the surface's model check and golden vectors
 * (tfit_golden_run), then the two-instrument ticks (tfit_region_pair: the
 * status, both forces and both states after every tick) and the surface
 * pairs, against the host reference's bits.  Prints per case
 *   LABEL case I: law W, surface W, pairs W, surface pairs W mismatching words
 * and a summary line; exit status 0 only when every check passes and every
 * word matches.  Each group of calls starts with a tfit_model_check call (a
 * marker in a traced image, below) and returns into a function named
 * region_golden_run*, so that
 * tests/firmware/trace_mix.c can tell the calls of one entry point apart.
 *
 * Compiled with -DREGION_H='"regions.h"' -DLABEL='"regions/board"'.
 */
#include "semihost.h"
#include "startup.h"
#include "tfit.h"

/* Inputs and expected outputs as float bit patterns (NaN and Inf tips). */
typedef struct region_case {
    const tfit_golden *law, *surf;
    uint32_t n_pair;
    const uint32_t *tip2;
    const int32_t *pstatus;
    const uint32_t *force2, *state2;
    uint32_t n_spair;
    const uint32_t *sstate2, *sforce2;
    const int32_t *sstatus;
    const uint32_t *sout;
} region_case;

#include REGION_H

/* Each group of calls starts with a model check.  The traced images
 * (-DREGION_TRACE, tests/region_target.mk) start it with an empty marker
 * instead: the untraced images check the same models, and a check's CRC
 * over a liver-sized surface's tables is as many executed blocks as all
 * the calls a trace counts. */
#ifdef REGION_TRACE
__attribute__((noinline)) static int trace_group_start(const tfit_model *m)
{
    __asm__ volatile("" ::: "memory");
    return m != 0;
}
#define GROUP_START(m) trace_group_start(m)
#else
#define GROUP_START(m) (tfit_model_check(m) == TFIT_OK)
#endif

#define SCRATCH_WORDS (3u * 512u)
static float scratch[SCRATCH_WORDS];

typedef union word {
    float f;
    uint32_t u;
} word;

static uint32_t bits(float x)
{
    word v;
    v.f = x;
    return v.u;
}

/* n floats from their bit patterns */
static void load(const uint32_t *w, uint32_t n, float *x)
{
    for (uint32_t i = 0u; i < n; ++i) {
        word v;
        v.u = w[i];
        x[i] = v.f;
    }
}

static __attribute__((noinline)) uint32_t region_golden_run_pairs(const region_case *c)
{
    uint32_t bad = 0u;
    float st[6], f[6], tip[6];
    (void)tfit_region_reset(c->law->model, st);
    (void)tfit_region_reset(c->law->model, st + 3);
    for (uint32_t v = 0u; v < c->n_pair; ++v) {
        load(c->tip2 + 6u * v, 6u, tip);
        const tfit_status s = tfit_region_pair(c->law->model, c->surf->model, st, tip, f);
        bad += (uint32_t)((int32_t)s != c->pstatus[v]);
        for (uint32_t i = 0u; i < 6u; ++i) {
            bad += (uint32_t)(bits(f[i]) != c->force2[6u * v + i]);
            bad += (uint32_t)(bits(st[i]) != c->state2[6u * v + i]);
        }
    }
    return bad;
}

static __attribute__((noinline)) uint32_t region_golden_run_surface_pairs(const region_case *c)
{
    uint32_t bad = 0u;
    const uint32_t n = 3u * c->surf->model->n_out;
    float st[6], f[6];
    for (uint32_t v = 0u; v < c->n_spair; ++v) {
        load(c->sstate2 + 6u * v, 6u, st);
        load(c->sforce2 + 6u * v, 6u, f);
        const tfit_status s = tfit_region_surface_pair(c->surf->model, st, f, scratch);
        bad += (uint32_t)((int32_t)s != c->sstatus[v]);
        for (uint32_t o = 0u; o < n; ++o) {
            bad += (uint32_t)(bits(scratch[o]) != c->sout[v * n + o]);
        }
    }
    return bad;
}

static void put(const char *s, uint32_t v)
{
    semihost_puts(s);
    semihost_put_u32(v);
}

int main(void)
{
    static const region_case *const cases[] = REGION_CASES;
    const uint32_t n_cases = (uint32_t)(sizeof cases / sizeof cases[0]);
    uint32_t passed = 0u, vectors = 0u;
    for (uint32_t i = 0u; i < n_cases; ++i) {
        const region_case *c = cases[i];
        if (3u * c->surf->model->n_out > SCRATCH_WORDS) {
            board_fail(LABEL ": a surface too large for the runner's scratch buffer");
        }
        uint32_t w[4];
        const int ok = GROUP_START(c->law->model);
        w[0] = tfit_golden_run(c->law, scratch);
        const int ok_s = GROUP_START(c->surf->model);
        w[1] = tfit_golden_run(c->surf, scratch);
        (void)GROUP_START(c->law->model); /* starts the pairs' group */
        w[2] = region_golden_run_pairs(c);
        (void)GROUP_START(c->surf->model); /* starts the surface pairs' group */
        w[3] = region_golden_run_surface_pairs(c);
        vectors += c->law->n_vec + c->surf->n_vec + c->n_pair + c->n_spair;
        semihost_puts(LABEL);
        put(" case ", i);
        put(ok && ok_s ? ": law " : ": MODEL CHECK FAILED, law ", w[0]);
        put(", surface ", w[1]);
        put(", pairs ", w[2]);
        put(", surface pairs ", w[3]);
        semihost_puts(" mismatching words\n");
        passed += (uint32_t)(ok && ok_s && (w[0] | w[1] | w[2] | w[3]) == 0u);
    }
    semihost_puts(LABEL);
    put(": ", passed);
    put(" of ", n_cases);
    put(" region cases bit-exact (", vectors);
    put(" vectors); stack used ", startup_stack_used());
    semihost_puts(" bytes\n");
    return passed == n_cases ? 0 : 1;
}
