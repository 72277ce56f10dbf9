/*
 * gen_random.c — writes random models with their golden vectors.
 *
 *   gen_random bundle N SEED FILE   N random models of the stateless families,
 *                                   then 200 prony models and 200 cut models, into
 *                                   a bundle (bundle.h)
 *   gen_random header SEED FILE.h   two small models per stateless family, a
 *                                   contact model of degree 1 and two prony
 *                                   models (nodal and modal static maps), three
 *                                   cut models (degrees 1, 2 and 0),
 *                                   through the real header emitter
 *                                   (FILE.h + FILE_golden.h)
 *
 * Expected outputs come from the host reference evaluator (ref_eval.c).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bundle.h"
#include "emit/emit_header.h"
#include "model/golden.h"
#include "random_model.h"
#include "model/ref_eval.h"

static void put(FILE *f, uint32_t w)
{
    unsigned char b[4] = {(unsigned char)w, (unsigned char)(w >> 8), (unsigned char)(w >> 16),
                          (unsigned char)(w >> 24)};
    fwrite(b, 1, 4, f);
}

static uint32_t bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, 4);
    return u;
}

static int write_model(FILE *f, const tf_model *m, uint64_t seed)
{
    float in[TF_GOLDEN_MAX][3];
    size_t n_vec = tf_golden_design(m, seed, in);
    float *out = malloc(n_vec * 3 * m->n_out * sizeof *out);
    int32_t status[TF_GOLDEN_MAX];
    if (out == NULL) {
        return -1;
    }
    put(f, (uint32_t)m->family);
    put(f, m->n_out);
    put(f, m->n_dims);
    put(f, m->n_coef);
    for (uint32_t i = 0; i < m->n_dims; ++i) {
        put(f, m->dims[i]);
    }
    for (uint32_t i = 0; i < m->n_coef; ++i) {
        put(f, bits(m->coef[i]));
    }
    for (uint32_t i = 0; i < m->n_out; ++i) {
        put(f, m->node_ids[i]);
    }
    uint32_t check[TFIT_CHECK_WORDS];
    if (tf_check_vector(m, check) != 0) {
        free(out);
        return -1;
    }
    for (int i = 0; i < TFIT_CHECK_WORDS; ++i) {
        put(f, check[i]);
    }
    put(f, tf_model_crc32_checked(m, check));
    put(f, (uint32_t)n_vec);
    for (size_t v = 0; v < n_vec; ++v) {
        for (int i = 0; i < 3; ++i) {
            put(f, bits(in[v][i]));
        }
    }
    tf_ref_run(m, (const float(*)[3])in, n_vec, status, out);
    for (size_t v = 0; v < n_vec; ++v) {
        put(f, (uint32_t)status[v]);
    }
    for (size_t w = 0; w < n_vec * 3 * m->n_out; ++w) {
        put(f, bits(out[w]));
    }
    free(out);
    return 0;
}

/* Prony models after the stateless ones, from their own sequence (the
 * first n models are those of earlier bundles). */
#define BUNDLE_PRONY 200
/* Cut models after those, from a third sequence. */
#define BUNDLE_CUT 200
/* modal_q15 models after those, from a fourth sequence. */
#define BUNDLE_Q15 100

static int bundle(long n, uint64_t seed, const char *path)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL) {
        perror(path);
        return 1;
    }
    tf_rng r = {seed}, rp = {seed ^ 0x9e3779b9u}, rc = {seed ^ 0x637574u},
           rq = {seed ^ 0x513135u};
    long per_family[TFIT_FAMILY_LAST + 1] = {0};
    const long total = n + BUNDLE_PRONY + BUNDLE_CUT + BUNDLE_Q15;
    put(f, TF_BUNDLE_MAGIC);
    put(f, (uint32_t)total);
    for (long i = 0; i < total; ++i) {
        char name[32];
        snprintf(name, sizeof name, "random%ld", i);
        tf_model *m = i < n                  ? tf_random_model(&r, name, 0, 0)
                      : i < n + BUNDLE_PRONY ? tf_random_model(&rp, name, TFIT_FAMILY_PRONY, 0)
                      : i < n + BUNDLE_PRONY + BUNDLE_CUT
                          ? tf_random_model(&rc, name, TFIT_FAMILY_CUT, 0)
                          : tf_random_model(&rq, name, TFIT_FAMILY_MODAL_Q15, 0);
        if (m == NULL || write_model(f, m, seed + (uint64_t)i) != 0) {
            fclose(f);
            return 1;
        }
        per_family[m->family]++;
        tf_model_free(m);
    }
    if (fclose(f) != 0) {
        perror(path);
        return 1;
    }
    printf("gen_random: %ld models (nodal %ld, modal %ld, zhou2017 %ld, contact %ld, prony %ld, "
           "cut %ld, modal_q15 %ld) -> %s\n",
           total, per_family[1], per_family[2], per_family[3], per_family[4], per_family[5],
           per_family[6], per_family[TFIT_FAMILY_MODAL_Q15], path);
    return 0;
}

/* A random contact model of degree 1 (the haptic loop's; its fast path):
 * drawn until the degree is 1, from its own sequence so that the other
 * models do not change. */
static tf_model *contact_degree1(uint64_t seed, const char *name)
{
    tf_rng r = {seed ^ 0xc0ffeeu};
    for (int tries = 0; tries < 1000; ++tries) {
        tf_model *m = tf_random_model(&r, name, TFIT_FAMILY_CONTACT, 1);
        if (m == NULL || m->dims[0] == 1) {
            return m;
        }
        tf_model_free(m);
    }
    return NULL;
}

/* A small prony model with a nodal (modal) static map and at least one
 * (two) terms, from its own sequence so that the other models do not
 * change. */
static tf_model *prony(uint64_t seed, const char *name, int modal)
{
    tf_rng r = {seed ^ (modal ? 0xbeefu : 0xfeedu)};
    for (int tries = 0; tries < 1000; ++tries) {
        tf_model *m = tf_random_model(&r, name, TFIT_FAMILY_PRONY, 1);
        if (m == NULL || ((m->dims[1] > 0) == modal && m->dims[2] >= 1u + (uint32_t)!modal)) {
            return m;
        }
        tf_model_free(m);
    }
    return NULL;
}

/* A small cut model of degree p (1: the fitter's; 0 and 2: the other
 * paths of tfit_cut.c), from its own sequence so that the other models do
 * not change. */
static tf_model *cut(uint64_t seed, const char *name, uint32_t p)
{
    tf_rng r = {seed ^ (0xc071u + p)};
    for (int tries = 0; tries < 1000; ++tries) {
        tf_model *m = tf_random_model(&r, name, TFIT_FAMILY_CUT, 1);
        if (m == NULL || m->dims[0] == p) {
            return m;
        }
        tf_model_free(m);
    }
    return NULL;
}

#define HEADER_MODELS 14

/* A small resonant model: static map nodal of degree p (p = 1: the
 * degree-1 rows), or modal, with at least `modes` modes, from its own
 * sequence. */
static tf_model *resonant(uint64_t seed, const char *name, int modal, uint32_t p, uint32_t modes)
{
    tf_rng r = {seed ^ (0x7e50u + 16u * (uint32_t)modal + p)};
    for (int tries = 0; tries < 10000; ++tries) {
        tf_model *m = tf_random_model(&r, name, TFIT_FAMILY_RESONANT, 1);
        if (m == NULL || ((m->dims[1] > 0) == modal && m->dims[2] >= modes &&
                          (modal || p == 0 || m->dims[0] == p))) {
            return m;
        }
        tf_model_free(m);
    }
    return NULL;
}

/* The resonant test header: three models (nodal p = 1, nodal any p, modal),
 * apart from families.h so that its models and the cycle model's
 * headers stay as they are. */
static int header_resonant(uint64_t seed, const char *path)
{
    tf_model *models[3] = {resonant(seed, "resonant_a", 0, 1, 1),
                           resonant(seed, "resonant_b", 0, 3, 2),
                           resonant(seed, "resonant_c", 1, 0, 3)};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int rc = 1;
    if (models[0] != NULL && models[1] != NULL && models[2] != NULL) {
        const tf_emit_info info = {.source = "random resonant test models "
                                             "(tests/bitexact/gen_random.c)",
                                   .golden_seed = seed};
        rc = tf_emit_header(&ctx, path, models, 3, &info);
        if (rc != 0) {
            fprintf(stderr, "gen_random: %s\n", ctx.err);
        }
    }
    for (int i = 0; i < 3; ++i) {
        tf_model_free(models[i]);
    }
    return rc != 0;
}

static int header(uint64_t seed, const char *path)
{
    static const char *const names[] = {"nodal_a", "nodal_b", "modal_a", "modal_b",
                                        "zhou_a", "zhou_b", "contact_a", "contact_b"};
    tf_model *models[HEADER_MODELS];
    tf_rng r = {seed};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    for (int i = 0; i < 8; ++i) {
        models[i] = tf_random_model(&r, names[i], (tfit_family)(1 + i / 2), 1);
        if (models[i] == NULL) {
            return 1;
        }
    }
    models[8] = contact_degree1(seed, "contact_p1");
    models[9] = prony(seed, "prony_a", 0);
    models[10] = prony(seed, "prony_b", 1);
    models[11] = cut(seed, "cut_a", 1);
    models[12] = cut(seed, "cut_b", 2);
    models[13] = cut(seed, "cut_c", 0);
    if (models[8] == NULL || models[9] == NULL || models[10] == NULL || models[11] == NULL ||
        models[12] == NULL || models[13] == NULL) {
        return 1;
    }
    const tf_emit_info info = {.source = "random test models (tests/bitexact/gen_random.c)",
                               .golden_seed = seed};
    int rc = tf_emit_header(&ctx, path, models, HEADER_MODELS, &info);
    for (int i = 0; i < HEADER_MODELS; ++i) {
        tf_model_free(models[i]);
    }
    if (rc != 0) {
        fprintf(stderr, "gen_random: %s\n", ctx.err);
        return 1;
    }
    return 0;
}

/* Modal models of ranks 1 .. MODAL_RANKS: every rank whose rows run in
 * assembly on Armv7E-M (TFIT_MODAL_ASM_MAX_RANK = 8) and the first above
 * it (the C rows), each at a random degree 0 .. 4 and 1 .. 8 outputs. */
#define MODAL_RANKS 9
#define MODAL_Q15_SHAPES 3

static int modal_ranks(uint64_t seed, const char *path)
{
    tf_model *models[MODAL_RANKS + MODAL_Q15_SHAPES] = {0};
    tf_rng r = {seed};
    char name[32];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int rc = 1;
    for (uint32_t k = 0; k < MODAL_RANKS; ++k) {
        const uint32_t dims[2] = {tf_rng_below(&r, 5), k + 1};
        snprintf(name, sizeof name, "modal_r%u", k + 1);
        models[k] = tf_random_model_of(&r, name, TFIT_FAMILY_MODAL, dims, 2,
                                       1 + tf_rng_below(&r, 8));
        if (models[k] == NULL) {
            goto done;
        }
    }
    /* then modal_q15 models (rank 8) of 1, 2 and 7 output points: the
     * assembly's odd point alone, one pair alone, both; degrees 1, 2, 4 */
    static const uint32_t q15_n_out[MODAL_Q15_SHAPES] = {1, 2, 7};
    static const uint32_t q15_p[MODAL_Q15_SHAPES] = {1, 2, 4};
    for (uint32_t k = 0; k < MODAL_Q15_SHAPES; ++k) {
        const uint32_t dims[2] = {q15_p[k], TFIT_MODAL_Q15_RANK};
        snprintf(name, sizeof name, "modal_q15_n%u", q15_n_out[k]);
        models[MODAL_RANKS + k] = tf_random_model_of(&r, name, TFIT_FAMILY_MODAL_Q15, dims, 2,
                                                     q15_n_out[k]);
        if (models[MODAL_RANKS + k] == NULL) {
            goto done;
        }
    }
    const tf_emit_info info = {.source = "random modal models of ranks 1-9, and modal_q15 "
                                         "models (tests/bitexact/gen_random.c)",
                               .golden_seed = seed};
    rc = tf_emit_header(&ctx, path, models, MODAL_RANKS + MODAL_Q15_SHAPES, &info);
    if (rc != 0) {
        fprintf(stderr, "gen_random: %s\n", ctx.err);
    }
done:
    for (int i = 0; i < MODAL_RANKS + MODAL_Q15_SHAPES; ++i) {
        tf_model_free(models[i]);
    }
    return rc != 0;
}

int main(int argc, char **argv)
{
    if (argc == 5 && strcmp(argv[1], "bundle") == 0) {
        return bundle(strtol(argv[2], NULL, 10), strtoull(argv[3], NULL, 10), argv[4]);
    }
    if (argc == 4 && strcmp(argv[1], "header-resonant") == 0) {
        return header_resonant(strtoull(argv[2], NULL, 10), argv[3]);
    }
    if (argc == 4 && strcmp(argv[1], "header") == 0) {
        return header(strtoull(argv[2], NULL, 10), argv[3]);
    }
    if (argc == 4 && strcmp(argv[1], "modal-ranks") == 0) {
        return modal_ranks(strtoull(argv[2], NULL, 10), argv[3]);
    }
    fprintf(stderr, "usage: gen_random bundle N SEED FILE | gen_random header[-resonant] SEED FILE.h | "
                    "gen_random modal-ranks SEED FILE.h\n");
    return 2;
}
