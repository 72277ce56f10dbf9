/*
 * gen_random.c — writes random models with their golden vectors.
 *
 *   gen_random bundle N SEED FILE   N random models into a bundle (bundle.h)
 *   gen_random header SEED FILE.h   two small models per family, and a contact
 *                                   model of degree 1, through the
 *                                   real header emitter (FILE.h + FILE_golden.h)
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
    size_t n_vec = tf_golden_inputs(m, seed, in);
    float *out = malloc(3 * m->n_out * sizeof *out);
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
    long status_at = ftell(f);
    for (size_t v = 0; v < n_vec; ++v) {
        put(f, 0);
    }
    for (size_t v = 0; v < n_vec; ++v) {
        status[v] = (int32_t)tf_ref_eval(m, in[v], out, NULL);
        for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
            put(f, bits(out[o]));
        }
    }
    long end = ftell(f);
    fseek(f, status_at, SEEK_SET);
    for (size_t v = 0; v < n_vec; ++v) {
        put(f, (uint32_t)status[v]);
    }
    fseek(f, end, SEEK_SET);
    free(out);
    return 0;
}

static int bundle(long n, uint64_t seed, const char *path)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL) {
        perror(path);
        return 1;
    }
    tf_rng r = {seed};
    long per_family[5] = {0};
    put(f, TF_BUNDLE_MAGIC);
    put(f, (uint32_t)n);
    for (long i = 0; i < n; ++i) {
        char name[32];
        snprintf(name, sizeof name, "random%ld", i);
        tf_model *m = tf_random_model(&r, name, 0, 0);
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
    printf("gen_random: %ld models (nodal %ld, modal %ld, zhou2017 %ld, contact %ld) -> %s\n", n,
           per_family[1], per_family[2], per_family[3], per_family[4], path);
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

static int header(uint64_t seed, const char *path)
{
    static const char *const names[] = {"nodal_a", "nodal_b", "modal_a", "modal_b",
                                        "zhou_a", "zhou_b", "contact_a", "contact_b"};
    tf_model *models[9];
    tf_rng r = {seed};
    char err[512];
    for (int i = 0; i < 8; ++i) {
        models[i] = tf_random_model(&r, names[i], (tfit_family)(1 + i / 2), 1);
        if (models[i] == NULL) {
            return 1;
        }
    }
    models[8] = contact_degree1(seed, "contact_p1");
    if (models[8] == NULL) {
        return 1;
    }
    const tf_emit_info info = {.source = "random test models (tests/bitexact/gen_random.c)",
                               .golden_seed = seed};
    int rc = tf_emit_header(path, models, 9, &info, err, sizeof err);
    for (int i = 0; i < 9; ++i) {
        tf_model_free(models[i]);
    }
    if (rc != 0) {
        fprintf(stderr, "gen_random: %s\n", err);
        return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 5 && strcmp(argv[1], "bundle") == 0) {
        return bundle(strtol(argv[2], NULL, 10), strtoull(argv[3], NULL, 10), argv[4]);
    }
    if (argc == 4 && strcmp(argv[1], "header") == 0) {
        return header(strtoull(argv[2], NULL, 10), argv[3]);
    }
    fprintf(stderr, "usage: gen_random bundle N SEED FILE | gen_random header SEED FILE.h\n");
    return 2;
}
