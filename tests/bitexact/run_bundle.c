/*
 * run_bundle.c — the bit-exact runner: loads every model of a bundle
 * (bundle.h), checks it with tfit_model_check() and runs its golden vectors
 * through the target library this binary was linked with.  Prints one line
 * and exits non-zero on any mismatch.
 *
 *   run_bundle LABEL FILE
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bundle.h"
#include "tfit.h"

static unsigned char *data;
static size_t size, pos;

static uint32_t get(void)
{
    if (pos + 4 > size) {
        fprintf(stderr, "run_bundle: truncated bundle\n");
        exit(2);
    }
    const unsigned char *b = data + pos;
    pos += 4;
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* Returns a pointer to n words in the file (aligned: every field is a word). */
static const uint32_t *words(uint32_t n)
{
    if (pos + 4ull * n > size) {
        fprintf(stderr, "run_bundle: truncated bundle\n");
        exit(2);
    }
    const uint32_t *w = (const uint32_t *)(data + pos);
    pos += 4ull * n;
    return w;
}

static int load(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        perror(path);
        return -1;
    }
    fseek(f, 0, SEEK_END);
    size = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    data = malloc(size);
    int ok = data != NULL && fread(data, 1, size, f) == size;
    fclose(f);
    return ok ? 0 : -1;
}

int main(int argc, char **argv)
{
    const uint32_t one = 1;
    if (argc != 3 || load(argv[2]) != 0) {
        fprintf(stderr, "usage: run_bundle LABEL FILE\n");
        return 2;
    }
    if (*(const unsigned char *)&one != 1 || get() != TF_BUNDLE_MAGIC) {
        fprintf(stderr, "run_bundle: %s is not a bundle (or this host is big-endian)\n", argv[2]);
        return 2;
    }
    uint32_t n_models = get();
    unsigned long vectors = 0, words_compared = 0, mismatches = 0, bad_checks = 0;
    float *scratch = NULL;
    for (uint32_t i = 0; i < n_models; ++i) {
        tfit_model m;
        m.api_version = TFIT_API_VERSION;
        m.family = get();
        m.n_out = get();
        m.n_dims = get();
        m.n_coef = get();
        m.dims = words(m.n_dims);
        m.coef = (const float *)words(m.n_coef);
        m.node_ids = words(m.n_out);
        m.dims_end = m.dims + m.n_dims;
        m.coef_end = m.coef + m.n_coef;
        m.node_ids_end = m.node_ids + m.n_out;
        for (int k = 0; k < TFIT_CHECK_WORDS; ++k) {
            m.check[k] = get();
        }
        m.crc32 = get();
        tfit_golden g = {.model = &m, .n_vec = get()};
        g.in = words(3 * g.n_vec);
        g.status = (const int32_t *)words(g.n_vec);
        g.out = words(g.n_vec * 3 * m.n_out);

        tfit_status st = tfit_model_check(&m);
        if (st != TFIT_OK) {
            fprintf(stderr, "%s: model %u (family %u): tfit_model_check = %d\n", argv[1], i,
                    m.family, (int)st);
            bad_checks++;
        }
        scratch = realloc(scratch, 3 * m.n_out * sizeof *scratch);
        uint32_t bad = tfit_golden_run(&g, scratch);
        if (bad != 0) {
            fprintf(stderr, "%s: model %u (family %u, n_out %u): %u mismatching words\n", argv[1],
                    i, m.family, m.n_out, bad);
        }
        mismatches += bad;
        vectors += g.n_vec;
        words_compared += g.n_vec * (1ul + 3ul * m.n_out);
    }
    free(scratch);
    free(data);
    printf("%-16s %u models, %lu vectors, %lu words compared: %lu mismatches, %lu failed checks\n",
           argv[1], n_models, vectors, words_compared, mismatches, bad_checks);
    return (mismatches == 0 && bad_checks == 0) ? 0 : 1;
}
