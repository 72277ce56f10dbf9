/*
 * probe_region.c — every call of the region entry points on the vectors of
 * a region bundle, once each, under callgrind, dumping the instruction
 * count of each call (CALLGRIND_DUMP_STATS_AT) so that insncount.sh can
 * compare them: the count must depend on neither the input nor the state.
 * Per region four sets: the law's golden ticks (tfit_region_force, from a
 * reset state: pressing, sliding, beyond the envelope, off the edge,
 * lifting, far, huge, subnormal, NaN and Inf tips), the surface's golden
 * vectors (tfit_region_surface at proxies on, between and beyond the grid
 * nodes, NaN states included), the two-instrument ticks (tfit_region_pair)
 * and the surface pairs (tfit_region_surface_pair).  Labels as
 * tests/insncount/probe.c's, with family 9 (law), 10 (surface), 11 (pair)
 * and 12 (surface pair).
 *
 *   probe_region FILE
 */
#include <string.h>
#include <valgrind/callgrind.h>

#include "region_read.h"

/* Negative control: a cost that depends on the input. */
static __attribute__((noinline)) float control_branchy(float x)
{
    float acc = 0.0f;
    for (int i = 0; i < 50 && acc < x; ++i) {
        acc += 1.0f;
    }
    return acc;
}

static void label(unsigned set, unsigned family, unsigned v, int status)
{
    char text[64];
    snprintf(text, sizeof text, "set=%u family=%u vec=%u status=%d", set, family, v, status);
    CALLGRIND_DUMP_STATS_AT(text);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: probe_region FILE\n");
        return 2;
    }
    region_reader r;
    uint32_t n;
    region_open(&r, argv[1], &n);
    for (uint32_t i = 0; i < n; ++i) {
        region_case c;
        region_read_case(&r, &c);
        float *out = malloc(3 * c.surf.m.n_out * sizeof *out);
        float st[6], f[6], x[6];
        tfit_status s;
        tfit_region_reset(&c.law.m, st);
        for (uint32_t v = 0; v < c.law.g.n_vec; ++v) {
            memcpy(x, c.law.g.in + 3 * v, 3 * sizeof *x);
            CALLGRIND_ZERO_STATS;
            s = tfit_region_force(&c.law.m, st, x, f);
            label(4 * i, 9, v, (int)s);
        }
        static const uint32_t frac[16] = TFIT_CUT_GOLDEN_S_BITS;
        for (uint32_t v = 0; v < c.surf.g.n_vec; ++v) {
            float gs[3], fr[2];
            memcpy(&fr[0], &frac[v & 15u], sizeof fr[0]);
            memcpy(&fr[1], &frac[(7u * v + 3u) & 15u], sizeof fr[1]);
            gs[0] = fr[0] * (float)(c.surf.m.dims[0] - 1u);
            gs[1] = fr[1] * (float)(c.surf.m.dims[1] - 1u);
            gs[2] = 1.0f;
            memcpy(x, c.surf.g.in + 3 * v, 3 * sizeof *x);
            CALLGRIND_ZERO_STATS;
            s = tfit_region_surface(&c.surf.m, gs, x, out);
            label(4 * i + 1, 10, v, (int)s);
        }
        tfit_region_reset(&c.law.m, st);
        tfit_region_reset(&c.law.m, st + 3);
        for (uint32_t v = 0; v < c.n_pair; ++v) {
            memcpy(x, c.tip2 + 6 * v, sizeof x);
            CALLGRIND_ZERO_STATS;
            s = tfit_region_pair(&c.law.m, &c.surf.m, st, x, f);
            label(4 * i + 2, 11, v, (int)s);
        }
        for (uint32_t v = 0; v < c.n_spair; ++v) {
            float st2[6];
            memcpy(st2, c.sstate2 + 6 * v, sizeof st2);
            memcpy(x, c.sforce2 + 6 * v, sizeof x);
            CALLGRIND_ZERO_STATS;
            s = tfit_region_surface_pair(&c.surf.m, st2, x, out);
            label(4 * i + 3, 12, v, (int)s);
        }
        free(out);
    }
    for (int v = 0; v < 3; ++v) {
        volatile float sink;
        CALLGRIND_ZERO_STATS;
        sink = control_branchy((float)(10 * v));
        (void)sink;
        label(9999, 0, (unsigned)v, 0);
    }
    free(r.data);
    return 0;
}
