/*
 * gen_region.c — random region models with their expected bits, from the
 * host reference evaluator (host/model/region_ref.c):
 *
 *   gen_region bundle N SEED FILE   N random regions (a law and a surface
 *                                   each; every third affine, with its
 *                                   two-instrument sequences) into a bundle
 *                                   (region_bundle.h)
 *   gen_region header SEED FILE.h MIXES.txt
 *                                   a C header for the firmware runner
 *                                   (qemu_region.c): five random regions and
 *                                   the cycle-measurement models (a block48-
 *                                   sized law, P = 2 on 17 x 17 sites, and a
 *                                   liver-sized surface, 400 outputs at rank 20
 *                                   and 40), as const tables with their golden
 *                                   and two-instrument vectors; MIXES.txt
 *                                   the cycle model's instruction mix of a
 *                                   call of each law and surface set on the
 *                                   M4F and the M7 ("m4f set S: MIX")
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cost/cycles.h"
#include "model/golden.h"
#include "model/model.h"
#include "model/ref_eval.h"
#include "model/region_pairs.h"
#include "model/region_ref.h"
#include "random_region.h"
#include "region_bundle.h"

typedef struct vectors {
    size_t n;
    float in[TF_GOLDEN_MAX][3];
    int32_t status[TF_GOLDEN_MAX];
    float *out; /* n x 3 n_out */
} vectors;

typedef tf_region_pairs pairs; /* model/region_pairs.h */

static int golden(const tf_model *m, uint64_t seed, vectors *v)
{
    v->n = tf_golden_design(m, seed, v->in);
    v->out = malloc(v->n * 3 * m->n_out * sizeof *v->out);
    if (v->out == NULL) {
        return -1;
    }
    tf_ref_run(m, (const float(*)[3])v->in, v->n, v->status, v->out);
    return 0;
}

static int pair_vectors(const tf_model *law, const tf_model *surf, uint64_t seed, pairs *p)
{
    return tf_region_pairs_design(law, surf, seed, p);
}

/* --- the bundle ------------------------------------------------------------------ */
static void put(FILE *f, uint32_t w)
{
    const unsigned char b[4] = {(unsigned char)w, (unsigned char)(w >> 8),
                                (unsigned char)(w >> 16), (unsigned char)(w >> 24)};
    fwrite(b, 1, 4, f);
}

static void put_floats(FILE *f, const float *x, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        uint32_t w;
        memcpy(&w, &x[i], sizeof w);
        put(f, w);
    }
}

static int write_model(tf_ctx *ctx, FILE *f, const tf_model *m, const vectors *v)
{
    uint32_t check[TFIT_CHECK_WORDS];
    if (tf_check_vector(m, check) != 0) {
        return tf_fail(ctx, "out of memory for the self-test of '%s'", m->name);
    }
    put(f, (uint32_t)m->family);
    put(f, m->n_out);
    put(f, m->n_dims);
    put(f, m->n_coef);
    for (uint32_t i = 0; i < m->n_dims; ++i) {
        put(f, m->dims[i]);
    }
    put_floats(f, m->coef, m->n_coef);
    for (uint32_t i = 0; i < m->n_out; ++i) {
        put(f, m->node_ids[i]);
    }
    for (int i = 0; i < TFIT_CHECK_WORDS; ++i) {
        put(f, check[i]);
    }
    put(f, tf_model_crc32_checked(m, check));
    put(f, (uint32_t)v->n);
    put_floats(f, &v->in[0][0], 3 * v->n);
    for (size_t i = 0; i < v->n; ++i) {
        put(f, (uint32_t)v->status[i]);
    }
    put_floats(f, v->out, v->n * 3 * m->n_out);
    return 0;
}

static void write_pairs(FILE *f, const tf_model *surf, const pairs *p)
{
    put(f, (uint32_t)p->n);
    put_floats(f, &p->tip[0][0], 6 * p->n);
    for (size_t i = 0; i < p->n; ++i) {
        put(f, (uint32_t)p->status[i]);
    }
    put_floats(f, &p->force[0][0], 6 * p->n);
    put_floats(f, &p->state[0][0], 6 * p->n);
    put(f, (uint32_t)p->ns);
    put_floats(f, &p->sstate[0][0], 6 * p->ns);
    put_floats(f, &p->sforce[0][0], 6 * p->ns);
    for (size_t i = 0; i < p->ns; ++i) {
        put(f, (uint32_t)p->sstatus[i]);
    }
    put_floats(f, p->sout, p->ns * 3 * surf->n_out);
}

/* A random region's law and surface: every third affine (P = 2, p = 1,
 * site modes: the two-instrument forms); the others of any degree. */
/* The shape of a region's models; 0 (-1 for site) draws at random. */
typedef struct shape {
    uint32_t degree, rank, p;
    int site;
    uint32_t n_out;
} shape;

static int shaped_pair(tf_ctx *ctx, tf_rng *r, long i, const shape *sh, tf_model **law,
                       tf_model **surf)
{
    tf_random_region g;
    char name[32];
    tf_random_region_draw(r, tf_rng_below(r, 8) == 0 ? 24 : 10, &g);
    const int aff = i % 3 == 0;
    if (aff) {
        g.degree = 2;
    }
    if (sh->degree != 0) {
        g.degree = sh->degree;
    }
    g.near = tf_rng_below(r, 3) == 0 ? 0 : 1 + tf_rng_below(r, TFIT_REGION_MAX_NEAR);
    uint32_t rank = tf_rng_below(r, 8) == 0 ? TFIT_REGION_MAX_RANK : 1 + tf_rng_below(r, 12);
    uint32_t p = aff ? 1 : 1 + tf_rng_below(r, TFIT_REGION_SURFACE_MAX_DEGREE);
    int site = aff || tf_rng_below(r, 2);
    rank = sh->rank != 0 ? sh->rank : rank;
    p = sh->p != 0 ? sh->p : p;
    site = sh->site >= 0 ? sh->site : site;
    uint32_t n_out = tf_rng_below(r, 10) == 0 ? 60 + tf_rng_below(r, 60) : 1 + tf_rng_below(r, 12);
    n_out = sh->n_out != 0 ? sh->n_out : n_out;
    snprintf(name, sizeof name, "law%ld", i);
    *law = tf_random_region_law(ctx, &g, name);
    snprintf(name, sizeof name, "surface%ld", i);
    *surf = *law == NULL ? NULL : tf_random_region_surface(ctx, r, &g, name, rank, p, site, n_out);
    return *surf == NULL ? -1 : 0;
}

static int random_pair(tf_ctx *ctx, tf_rng *r, long i, tf_model **law, tf_model **surf)
{
    const shape any = {0, 0, 0, -1, 0};
    return shaped_pair(ctx, r, i, &any, law, surf);
}

static int bundle(long n, uint64_t seed, const char *path)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    FILE *f = fopen(path, "wb");
    if (f == NULL) {
        perror(path);
        return 1;
    }
    tf_rng r = {seed};
    long n_pairs = 0, n_vec = 0;
    put(f, TF_REGION_BUNDLE_MAGIC);
    put(f, (uint32_t)n);
    for (long i = 0; i < n; ++i) {
        tf_model *law = NULL, *surf = NULL;
        vectors vl = {0}, vs = {0};
        pairs *p = calloc(1, sizeof *p);
        int rc = p == NULL || random_pair(&ctx, &r, i, &law, &surf) != 0 ||
                 golden(law, seed + 2 * (uint64_t)i, &vl) != 0 ||
                 golden(surf, seed + 2 * (uint64_t)i + 1, &vs) != 0 ||
                 pair_vectors(law, surf, seed + 3 * (uint64_t)i, p) != 0 ||
                 write_model(&ctx, f, law, &vl) != 0 || write_model(&ctx, f, surf, &vs) != 0;
        if (rc == 0) {
            write_pairs(f, surf, p);
            n_pairs += p->n > 0;
            n_vec += (long)(vl.n + vs.n + p->n + p->ns);
        }
        free(vl.out);
        free(vs.out);
        if (p != NULL) {
            free(p->sout);
        }
        free(p);
        tf_model_free(law);
        tf_model_free(surf);
        if (rc != 0) {
            fprintf(stderr, "gen_region: region %ld: %s\n", i, ctx.err);
            fclose(f);
            return 1;
        }
    }
    if (fclose(f) != 0) {
        perror(path);
        return 1;
    }
    printf("gen_region: %ld regions (law + surface), %ld with two-instrument sequences, %ld "
           "vectors -> %s\n", n, n_pairs, n_vec, path);
    return 0;
}

/* --- the firmware header --------------------------------------------------------- */
static void words(FILE *f, const char *type, const char *name, const uint32_t *w, size_t n)
{
    fprintf(f, "static const %s %s[%zu] = {", type, name, n == 0 ? (size_t)1 : n);
    for (size_t i = 0; i < n; ++i) {
        fprintf(f, "%s0x%08xu,", i % 8 == 0 ? "\n    " : " ", w[i]);
    }
    fprintf(f, "%s};\n", n == 0 ? "0" : "\n");
}

static void floats(FILE *f, const char *name, const float *x, size_t n)
{
    fprintf(f, "static const float %s[%zu] = {", name, n == 0 ? (size_t)1 : n);
    for (size_t i = 0; i < n; ++i) {
        fprintf(f, "%s%a,", i % 6 == 0 ? "\n    " : " ", (double)x[i]);
    }
    fprintf(f, "%s};\n", n == 0 ? "0" : "\n");
}

static void statuses(FILE *f, const char *name, const int32_t *s, size_t n)
{
    fprintf(f, "static const int32_t %s[%zu] = {", name, n == 0 ? (size_t)1 : n);
    for (size_t i = 0; i < n; ++i) {
        fprintf(f, "%s%d,", i % 16 == 0 ? "\n    " : " ", (int)s[i]);
    }
    fprintf(f, "%s};\n", n == 0 ? "0" : "\n");
}

static uint32_t *bits_of(const float *x, size_t n)
{
    uint32_t *w = malloc((n == 0 ? 1 : n) * sizeof *w);
    if (w != NULL) {
        memcpy(w, x, n * sizeof *w);
    }
    return w;
}

/* One model as a const tfit_model with its golden set; `tag` names it. */
static int header_model(tf_ctx *ctx, FILE *f, const tf_model *m, const vectors *v,
                        const char *tag)
{
    uint32_t check[TFIT_CHECK_WORDS];
    char name[96];
    if (tf_check_vector(m, check) != 0) {
        return tf_fail(ctx, "out of memory for the self-test of '%s'", m->name);
    }
    snprintf(name, sizeof name, "%s_dims", tag);
    words(f, "uint32_t", name, m->dims, m->n_dims);
    snprintf(name, sizeof name, "%s_nodes", tag);
    words(f, "uint32_t", name, m->node_ids, m->n_out);
    snprintf(name, sizeof name, "%s_coef", tag);
    floats(f, name, m->coef, m->n_coef);
    fprintf(f, "static const tfit_model %s = {%uu, %uu, %uu, %uu, %uu, %s_dims, %s_coef, "
               "%s_nodes,\n    %s_dims + %u, %s_coef + %u, %s_nodes + %u, {",
            tag, (unsigned)TFIT_API_VERSION, (unsigned)m->family, m->n_out, m->n_dims, m->n_coef,
            tag, tag, tag, tag, m->n_dims, tag, m->n_coef, tag, m->n_out);
    for (int i = 0; i < TFIT_CHECK_WORDS; ++i) {
        fprintf(f, "%s0x%08xu", i ? ", " : "", check[i]);
    }
    fprintf(f, "},\n    0x%08xu};\n", tf_model_crc32_checked(m, check));
    uint32_t *in = bits_of(&v->in[0][0], 3 * v->n), *out = bits_of(v->out, v->n * 3 * m->n_out);
    if (in == NULL || out == NULL) {
        free(in);
        free(out);
        return tf_fail(ctx, "out of memory");
    }
    snprintf(name, sizeof name, "%s_gin", tag);
    words(f, "uint32_t", name, in, 3 * v->n);
    snprintf(name, sizeof name, "%s_gstatus", tag);
    statuses(f, name, v->status, v->n);
    snprintf(name, sizeof name, "%s_gout", tag);
    words(f, "uint32_t", name, out, v->n * 3 * m->n_out);
    fprintf(f, "static const tfit_golden %s_golden = {&%s, %zuu, %s_gin, %s_gstatus, %s_gout};\n\n",
            tag, tag, v->n, tag, tag, tag);
    free(in);
    free(out);
    return 0;
}

static int header_pairs(tf_ctx *ctx, FILE *f, const tf_model *surf, const pairs *p,
                        const char *tag)
{
    char name[96];
    uint32_t *sout = bits_of(p->sout, p->ns * 3 * surf->n_out);
    if (sout == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    snprintf(name, sizeof name, "%s_ptip", tag);
    words(f, "uint32_t", name, (const uint32_t *)(const void *)&p->tip[0][0], 6 * p->n);
    snprintf(name, sizeof name, "%s_pstatus", tag);
    statuses(f, name, p->status, p->n);
    snprintf(name, sizeof name, "%s_pforce", tag);
    words(f, "uint32_t", name, (const uint32_t *)(const void *)&p->force[0][0], 6 * p->n);
    snprintf(name, sizeof name, "%s_pstate", tag);
    words(f, "uint32_t", name, (const uint32_t *)(const void *)&p->state[0][0], 6 * p->n);
    snprintf(name, sizeof name, "%s_sstate", tag);
    words(f, "uint32_t", name, (const uint32_t *)(const void *)&p->sstate[0][0], 6 * p->ns);
    snprintf(name, sizeof name, "%s_sforce", tag);
    words(f, "uint32_t", name, (const uint32_t *)(const void *)&p->sforce[0][0], 6 * p->ns);
    snprintf(name, sizeof name, "%s_sstatus", tag);
    statuses(f, name, p->sstatus, p->ns);
    snprintf(name, sizeof name, "%s_sout", tag);
    words(f, "uint32_t", name, sout, p->ns * 3 * surf->n_out);
    free(sout);
    return 0;
}

/* Regions 0, 2, 3 affine (the two-instrument forms), 1 and 4 of higher
 * degrees; then the cycle models (cases 5 and 6, groups 20-27). */
#define HEADER_REGIONS 5
/* The cycle cases keep a few vectors of each kind (the traces under QEMU
 * log every block executed): the law's 80 ticks, 4 surface vectors, 16
 * two-instrument ticks, 4 surface pairs. */
#define HEADER_MAX_VEC 4
#define HEADER_MAX_PAIRS 16

/* The cycle models: a block48-sized law and liver-sized surfaces. */
static int cycle_models(tf_ctx *ctx, tf_rng *r, tf_model **law, tf_model *surf[2])
{
    tf_random_region g;
    tf_random_region_block(&g, 17, 2.4, 0.5, 1.2, 0.3, 0.5, 2, 0.3);
    *law = tf_random_region_law(ctx, &g, "block48_law");
    if (*law == NULL) {
        return -1;
    }
    g.near = 9; /* block48's near field (outputs within 1.5 probe widths) */
    surf[0] = tf_random_region_surface(ctx, r, &g, "liver_r20", 20, 1, 1, 400);
    g.near = 0;
    surf[1] = surf[0] == NULL ? NULL
                              : tf_random_region_surface(ctx, r, &g, "liver_r40", 40, 1, 1, 400);
    return surf[1] == NULL ? -1 : 0;
}

/* The cycle model's mix of one call (model/forms/region*.c) on each core,
 * for the QEMU trace's set `set` (qemu_region.c runs four groups a case:
 * the law, the surface, the pairs, the surface pairs). */
static void predicted_mix(FILE *f, const tf_model *m, size_t set)
{
    static const char *const cores[TF_CORES] = {"m4f", "m7"};
    for (int c = 0; c < TF_CORES; ++c) {
        tf_insn_mix mix;
        char text[512];
        tf_model_insn_mix(m, (tf_core)c, &mix);
        tf_insn_mix_format(&mix, text, sizeof text);
        fprintf(f, "%s set %zu: %s\n", cores[c], set, text);
    }
}

static int header(uint64_t seed, const char *path, const char *mix_path)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        perror(path);
        return 1;
    }
    fprintf(f, "/* %s - random region models and their expected bits, written by "
               "tests/region/gen_region.c (seed %llu); run by qemu_region.c */\n"
               "#include \"tfit.h\"\n\n", path, (unsigned long long)seed);
    FILE *mf = fopen(mix_path, "w");
    if (mf == NULL) {
        perror(mix_path);
        fclose(f);
        return 1;
    }
    tf_rng r = {seed};
    int rc = 0;
    char tag[32];
    size_t sets = 0, n_pairs = 0;
    for (int i = 0; i < HEADER_REGIONS + 1 && rc == 0; ++i) {
        tf_model *law = NULL, *surf[2] = {NULL, NULL};
        const int cycles = i == HEADER_REGIONS;
        /* small ones (the traces log every block): ranks 1-8 run the modal
         * rows' assembly, 9 and 11 its C loop */
        static const shape shapes[HEADER_REGIONS] = {{0, 6, 0, -1, 9},
                                                     {4, 6, 2, 0, 5},
                                                     {0, 3, 0, -1, 7},
                                                     {0, 11, 0, -1, 4},
                                                     {3, 9, 3, 1, 6}};
        rc = cycles ? cycle_models(&ctx, &r, &law, surf)
                    : shaped_pair(&ctx, &r, (i == 1 || i == 4) ? 1 : 3 * i, &shapes[i], &law,
                                  &surf[0]);
        for (int s = 0; s < (cycles ? 2 : 1) && rc == 0; ++s) {
            vectors vl = {0}, vs = {0};
            pairs *p = calloc(1, sizeof *p);
            rc = p == NULL || (s == 0 && golden(law, seed + 2 * (uint64_t)i, &vl) != 0) ||
                 golden(surf[s], seed + 2 * (uint64_t)i + 1, &vs) != 0 ||
                 pair_vectors(law, surf[s], seed + 3 * (uint64_t)i, p) != 0;
            if (rc == 0 && cycles) { /* the liver-sized surfaces: a few vectors */
                vs.n = vs.n < HEADER_MAX_VEC ? vs.n : HEADER_MAX_VEC;
                p->ns = p->ns < HEADER_MAX_VEC ? p->ns : HEADER_MAX_VEC;
                p->n = p->n < HEADER_MAX_PAIRS ? p->n : HEADER_MAX_PAIRS;
            }
            if (rc == 0) {
                predicted_mix(mf, law, 4 * (size_t)(i + s));
                predicted_mix(mf, surf[s], 4 * (size_t)(i + s) + 1);
            }
            if (rc == 0 && s == 0) {
                snprintf(tag, sizeof tag, "region%d_law", i);
                rc = header_model(&ctx, f, law, &vl, tag);
                sets++;
            }
            if (rc == 0) {
                snprintf(tag, sizeof tag, "region%d_surface%d", i, s);
                rc = header_model(&ctx, f, surf[s], &vs, tag) ||
                     header_pairs(&ctx, f, surf[s], p, tag);
                fprintf(f, "static const region_case region%d_case%d = {&region%d_law_golden, "
                           "&%s_golden, %zuu, %s_ptip, %s_pstatus, %s_pforce, %s_pstate, %zuu, "
                           "%s_sstate, %s_sforce, %s_sstatus, %s_sout};\n\n",
                        i, s, i, tag, p->n, tag, tag, tag, tag, p->ns, tag, tag, tag, tag);
                sets++;
                n_pairs++;
            }
            free(vl.out);
            free(vs.out);
            if (p != NULL) {
                free(p->sout);
            }
            free(p);
        }
        tf_model_free(law);
        tf_model_free(surf[0]);
        tf_model_free(surf[1]);
    }
    fprintf(f, "#define REGION_CASES {");
    for (int i = 0; i < HEADER_REGIONS; ++i) {
        fprintf(f, "&region%d_case0, ", i);
    }
    fprintf(f, "&region%d_case0, &region%d_case1}\n", HEADER_REGIONS, HEADER_REGIONS);
    if ((fclose(mf) != 0) | (fclose(f) != 0) || rc != 0) {
        fprintf(stderr, "gen_region: %s\n", rc ? ctx.err : "write failed");
        return 1;
    }
    printf("gen_region: %zu models in %zu cases -> %s\n", sets, n_pairs, path);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 5 && strcmp(argv[1], "bundle") == 0) {
        return bundle(strtol(argv[2], NULL, 10), strtoull(argv[3], NULL, 10), argv[4]);
    }
    if (argc == 5 && strcmp(argv[1], "header") == 0) {
        return header(strtoull(argv[2], NULL, 10), argv[3], argv[4]);
    }
    fprintf(stderr,
            "usage: gen_region bundle N SEED FILE | gen_region header SEED FILE.h MIXES.txt\n");
    return 2;
}
