/*
 * tick_paths.c — one path through the code for every tick of a long random
 * palpation: libtfit built with GCC's -fsanitize-coverage=trace-pc, which
 * calls __sanitizer_cov_trace_pc() at the start of every basic block.
 * Around each call of a region entry point this program counts the blocks
 * and hashes their addresses in order; every call of an entry point on one
 * model must give the same count and hash — the same sequence of basic
 * blocks, hence the same instructions — whatever the tip, the proxy's
 * state and the status.  (callgrind counts the instructions of the -O2
 * build itself for every golden input and state: check-insncount-region.)
 *
 * The palpation, per model (the shipped coeffs/block48_region.h and every
 * region of a bundle, region_bundle.h): the tip moves in straight segments
 * of 20 to 2,000 ticks towards the law's golden tips chosen at random
 * (pressing, sliding, beyond the envelope, off the edge, lifting: the
 * golden set's finite tips, and points between two of them), with a jitter
 * of up to 0.05 mm a tick; after one segment in four one coordinate of the
 * tip is NaN, Inf or 1e30 for one tick.  Each tick
 * calls tfit_region_force; every 16th tick tfit_region_surface with the
 * state and that force (the display).  For an affine model (two-instrument
 * vectors in its golden set) one segment in four moves two tips at once
 * through tfit_region_pair, and its display through
 * tfit_region_surface_pair.  The ticks are shared equally among the
 * models.  A negative control, a loop whose length depends on its input
 * (tick_control.c, built with the same instrumentation), must give more
 * than one path.
 *
 *   tick_paths BUNDLE TICKS SEED
 *
 * Prints one line per model and entry point (calls, blocks a call, the
 * statuses seen) and a result line; exit 1 when a call took another path,
 * when the control did not, or when no call of a model saw contact.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "block48_region_golden.h"
#include "region_read.h"

float tick_control(float x);

/* The path of the calls since the last arm(): blocks counted and their
 * addresses hashed in order (FNV-1a over the 8 bytes of each). */
static int armed;
static uint64_t n_blocks, path_hash;

void __sanitizer_cov_trace_pc(void);
void __sanitizer_cov_trace_pc(void)
{
    if (armed) {
        uint64_t a = (uint64_t)(uintptr_t)__builtin_return_address(0);
        for (int i = 0; i < 8; ++i) {
            path_hash = (path_hash ^ ((a >> (8 * i)) & 0xffu)) * 0x100000001b3ull;
        }
        ++n_blocks;
    }
}

static void arm(void)
{
    n_blocks = 0;
    path_hash = 0xcbf29ce484222325ull;
    armed = 1;
}

/* One entry point's calls on one model: the first call's path, the calls
 * that took another, and the statuses seen (index: status + 8). */
typedef struct entry {
    const char *name;
    uint64_t calls, blocks, hash, other;
    uint64_t status_seen[11];
} entry;

static void record(entry *e, tfit_status s)
{
    armed = 0;
    if (e->calls == 0) {
        e->blocks = n_blocks;
        e->hash = path_hash;
    } else if (n_blocks != e->blocks || path_hash != e->hash) {
        if (e->other == 0) {
            fprintf(stderr, "%s: call %llu took %llu blocks against %llu\n", e->name,
                    (unsigned long long)e->calls, (unsigned long long)n_blocks,
                    (unsigned long long)e->blocks);
        }
        ++e->other;
    }
    ++e->calls;
    e->status_seen[(int)s + 8 >= 0 && (int)s + 8 < 11 ? (int)s + 8 : 0]++;
}

typedef struct rng {
    uint64_t s;
} rng;

static uint32_t next(rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(r->s >> 33);
}

static float uniform(rng *r) /* [0, 1) */
{
    return (float)(next(r) >> 8) * (1.0f / 16777216.0f);
}

/* A model to palpate: its law and surface, the finite golden tips. */
typedef struct subject {
    const char *name;
    const tfit_model *law, *surf;
    const float *tips; /* 3 n_tips */
    uint32_t n_tips;
    int affine;
} subject;

/* A point between two golden tips chosen at random. */
static void pick(rng *r, const subject *m, float to[3])
{
    const float *a = m->tips + 3 * (next(r) % m->n_tips);
    const float *b = m->tips + 3 * (next(r) % m->n_tips);
    const float w = uniform(r);
    for (int k = 0; k < 3; ++k) {
        to[k] = a[k] + w * (b[k] - a[k]);
    }
}

static void step_tip(rng *r, float tip[3], const float to[3], uint32_t left)
{
    for (int k = 0; k < 3; ++k) {
        tip[k] += (to[k] - tip[k]) / (float)left + 0.1f * (uniform(r) - 0.5f);
    }
}

static void bad_tip(rng *r, float tip[3])
{
    static const float bad[3] = {NAN, INFINITY, 1e30f};
    tip[next(r) % 3u] = bad[next(r) % 3u];
}

/* entries: force, surface, pair, surface pair */
static void palpate(const subject *m, uint64_t ticks, rng *r, entry e[4])
{
    float st[2 * TFIT_REGION_STATE_WORDS], f[6], tip[6], to[6];
    float *out = malloc(3 * m->surf->n_out * sizeof *out);
    if (out == NULL) {
        fprintf(stderr, "tick_paths: out of memory\n");
        exit(1);
    }
    tfit_region_reset(m->law, st);
    tfit_region_reset(m->law, st + TFIT_REGION_STATE_WORDS);
    pick(r, m, tip);
    pick(r, m, tip + 3);
    uint64_t t = 0;
    while (t < ticks) {
        const uint32_t len = 20u + next(r) % 1981u;
        const int two = m->affine && next(r) % 4u == 0u;
        pick(r, m, to);
        pick(r, m, to + 3);
        for (uint32_t i = 0; i < len && t < ticks; ++i, ++t) {
            step_tip(r, tip, to, len - i);
            if (two) {
                step_tip(r, tip + 3, to + 3, len - i);
                arm();
                record(&e[2], tfit_region_pair(m->law, m->surf, st, tip, f));
            } else {
                arm();
                record(&e[0], tfit_region_force(m->law, st, tip, f));
            }
            if (t % 16u == 0u) {
                arm();
                if (two) {
                    record(&e[3], tfit_region_surface_pair(m->surf, st, f, out));
                } else {
                    record(&e[1], tfit_region_surface(m->surf, st, f, out));
                }
            }
        }
        if (next(r) % 4u == 0u && t < ticks) { /* one tick of a bad tip */
            float keep[3];
            memcpy(keep, tip, sizeof keep);
            bad_tip(r, tip);
            arm();
            if (two) {
                record(&e[2], tfit_region_pair(m->law, m->surf, st, tip, f));
            } else {
                record(&e[0], tfit_region_force(m->law, st, tip, f));
            }
            memcpy(tip, keep, sizeof keep);
            ++t;
        }
    }
    free(out);
}

/* The finite golden tips of a law (bits -> floats), in a new array. */
static float *finite_tips(const uint32_t *bits, uint32_t n, uint32_t *n_finite)
{
    float *t = malloc(3 * (n ? n : 1) * sizeof *t);
    *n_finite = 0;
    for (uint32_t v = 0; t != NULL && v < n; ++v) {
        float x[3];
        memcpy(x, bits + 3 * v, sizeof x);
        if (isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]) &&
            fabsf(x[0]) + fabsf(x[1]) + fabsf(x[2]) < 1e4f) {
            memcpy(t + 3 * (*n_finite)++, x, sizeof x);
        }
    }
    return t;
}

static int report(const subject *m, const entry e[4])
{
    static const char *const status[11] = {"arith", "range", "corrupt", "version", "size",
                                           "family", "arg", "bad-input", "ok", "clamped",
                                           "no-contact"};
    int bad = 0;
    for (int k = 0; k < 4; ++k) {
        if (e[k].calls == 0) {
            continue;
        }
        printf("%-17s %-25s %6llu calls, %4llu blocks a call, %s;", m->name, e[k].name,
               (unsigned long long)e[k].calls, (unsigned long long)e[k].blocks,
               e[k].other ? "OTHER PATHS" : "one path");
        for (int s = 0; s < 11; ++s) {
            if (e[k].status_seen[s]) {
                printf(" %s %llu", status[s], (unsigned long long)e[k].status_seen[s]);
            }
        }
        printf("\n");
        bad |= e[k].other != 0;
    }
    for (int k = 0; k < 4; k += 2) {
        if (e[k].calls && (e[k].status_seen[8 + TFIT_OK] == 0 ||
                           e[k].status_seen[8 + TFIT_ERR_INPUT] == 0)) {
            printf("%s, %s: no tick in contact, or none with a bad tip\n", m->name, e[k].name);
            bad = 1;
        }
    }
    return bad;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: tick_paths BUNDLE TICKS SEED\n");
        return 2;
    }
    const uint64_t ticks = strtoull(argv[2], NULL, 10);
    rng r = {strtoull(argv[3], NULL, 10)};
    region_reader rd;
    uint32_t n;
    region_open(&rd, argv[1], &n);
    const uint64_t each = ticks / (n + 1u);
    uint64_t total = 0, models = 0;
    int bad = 0;
    for (uint32_t i = 0; i <= n; ++i) {
        region_case c;
        subject m;
        char name[32];
        const uint32_t *bits;
        uint32_t n_vec;
        if (i == 0) { /* the shipped block48 region */
            m = (subject){"block48_region", &tfit_block48_region_law,
                          &tfit_block48_region_surface, NULL, 0, 1};
            bits = tfit_block48_region_law_golden.in;
            n_vec = tfit_block48_region_law_golden.n_vec;
        } else {
            region_read_case(&rd, &c);
            snprintf(name, sizeof name, "bundle region %u", i - 1);
            m = (subject){name, &c.law.m, &c.surf.m, NULL, 0, c.n_pair > 0};
            bits = c.law.g.in;
            n_vec = c.law.g.n_vec;
        }
        float *tips = finite_tips(bits, n_vec, &m.n_tips);
        if (tips == NULL || m.n_tips == 0) {
            fprintf(stderr, "%s: no finite golden tip\n", m.name);
            return 1;
        }
        m.tips = tips;
        entry e[4] = {{.name = "tfit_region_force"},
                      {.name = "tfit_region_surface"},
                      {.name = "tfit_region_pair"},
                      {.name = "tfit_region_surface_pair"}};
        palpate(&m, i == n ? ticks - total : each, &r, e);
        bad |= report(&m, e);
        for (int k = 0; k < 4; ++k) {
            total += k == 0 || k == 2 ? e[k].calls : 0;
        }
        free(tips);
        ++models;
    }
    free(rd.data);
    uint64_t control[3];
    for (int v = 0; v < 3; ++v) {
        arm();
        volatile float sink = tick_control((float)(10 * v));
        (void)sink;
        armed = 0;
        control[v] = n_blocks;
    }
    if (control[0] == control[1] || control[1] == control[2]) {
        printf("control: an input-dependent loop gave one path: the instrumentation is not seen\n");
        bad = 1;
    } else {
        printf("control (a loop whose length depends on its input): %llu, %llu, %llu blocks\n",
               (unsigned long long)control[0], (unsigned long long)control[1],
               (unsigned long long)control[2]);
    }
    printf("%s: %llu ticks of a random palpation over %llu models%s\n",
           bad ? "FAILED" : "ok", (unsigned long long)total, (unsigned long long)models,
           bad ? "" : ": every call of an entry point took one sequence of basic blocks");
    return bad;
}
