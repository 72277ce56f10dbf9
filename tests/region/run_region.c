/*
 * run_region.c — the bit-exact runner of the region models: loads every
 * region of a bundle (region_bundle.h), checks both models with
 * tfit_model_check(), runs their golden vectors (tfit_golden_run: the law's
 * tick sequence, the surface at its golden proxies) and the two-instrument
 * sequences (tfit_region_pair: status, forces and both states after every
 * tick; tfit_region_surface_pair) through the target library this binary
 * was linked with, and counts the words that differ from the host
 * reference's.  Prints one line; exits non-zero on any mismatch.
 *
 *   run_region LABEL FILE
 */
#include <string.h>

#include "region_read.h"

static uint32_t bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* tfit_region_pair from two reset states; mismatching words */
static unsigned long run_pairs(const region_case *c)
{
    unsigned long bad = 0;
    float st[6], f[6];
    tfit_region_reset(&c->law.m, st);
    tfit_region_reset(&c->law.m, st + 3);
    for (uint32_t v = 0; v < c->n_pair; ++v) {
        const tfit_status s = tfit_region_pair(&c->law.m, &c->surf.m, st, c->tip2 + 6 * v, f);
        bad += (int32_t)s != c->pstatus[v];
        for (int i = 0; i < 6; ++i) {
            bad += bits(f[i]) != c->force2[6 * v + i];
            bad += bits(st[i]) != c->state2[6 * v + i];
        }
    }
    return bad;
}

static unsigned long run_surface_pairs(const region_case *c, float *out)
{
    unsigned long bad = 0;
    const uint32_t n = 3 * c->surf.m.n_out;
    for (uint32_t v = 0; v < c->n_spair; ++v) {
        const tfit_status s =
            tfit_region_surface_pair(&c->surf.m, c->sstate2 + 6 * v, c->sforce2 + 6 * v, out);
        bad += (int32_t)s != c->sstatus[v];
        for (uint32_t o = 0; o < n; ++o) {
            bad += bits(out[o]) != c->sout[(size_t)v * n + o];
        }
    }
    return bad;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: run_region LABEL FILE\n");
        return 2;
    }
    region_reader r;
    uint32_t n;
    region_open(&r, argv[2], &n);
    unsigned long vectors = 0, words = 0, mismatches = 0, bad_checks = 0, pair_ticks = 0;
    float *scratch = NULL;
    for (uint32_t i = 0; i < n; ++i) {
        region_case c;
        region_read_case(&r, &c);
        region_model *ms[2] = {&c.law, &c.surf};
        scratch = realloc(scratch, 3 * c.surf.m.n_out * sizeof *scratch + 16);
        for (int k = 0; k < 2; ++k) {
            const tfit_status st = tfit_model_check(&ms[k]->m);
            if (st != TFIT_OK) {
                fprintf(stderr, "%s: region %u %s: tfit_model_check = %d\n", argv[1], i,
                        k ? "surface" : "law", (int)st);
                bad_checks++;
            }
            const uint32_t bad = tfit_golden_run(&ms[k]->g, scratch);
            if (bad != 0) {
                fprintf(stderr, "%s: region %u %s: %u mismatching words\n", argv[1], i,
                        k ? "surface" : "law", bad);
            }
            mismatches += bad;
            vectors += ms[k]->g.n_vec;
            words += ms[k]->g.n_vec * (1ul + 3ul * ms[k]->m.n_out);
        }
        const unsigned long bp = run_pairs(&c), bs = run_surface_pairs(&c, scratch);
        if (bp + bs != 0) {
            fprintf(stderr, "%s: region %u: %lu pair and %lu surface-pair mismatching words\n",
                    argv[1], i, bp, bs);
        }
        mismatches += bp + bs;
        vectors += c.n_pair + c.n_spair;
        pair_ticks += c.n_pair;
        words += c.n_pair * 13ul + c.n_spair * (1ul + 3ul * c.surf.m.n_out);
    }
    free(scratch);
    free(r.data);
    printf("%-16s %u regions, %lu vectors (%lu two-instrument ticks), %lu words compared: "
           "%lu mismatches, %lu failed checks\n",
           argv[1], n, vectors, pair_ticks, words, mismatches, bad_checks);
    return (mismatches == 0 && bad_checks == 0) ? 0 : 1;
}
