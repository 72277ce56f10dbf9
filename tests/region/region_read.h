/*
 * region_read.h — reads a region bundle (region_bundle.h) into target
 * descriptors, for the bit-exact runner and the instruction-count probe
 * (header-only: both are built against a target library alone).
 */
#ifndef TF_REGION_READ_H
#define TF_REGION_READ_H

#include <stdio.h>
#include <stdlib.h>

#include "region_bundle.h"
#include "tfit.h"

typedef struct region_reader {
    unsigned char *data;
    size_t size, pos;
} region_reader;

/* One model and its golden vectors, pointing into the bundle. */
typedef struct region_model {
    tfit_model m;
    tfit_golden g;
} region_model;

/* A region: its law, its surface and the two-instrument sequences. */
typedef struct region_case {
    region_model law, surf;
    uint32_t n_pair;
    const float *tip2;       /* 6 n_pair */
    const int32_t *pstatus;  /* n_pair */
    const uint32_t *force2;  /* 6 n_pair bits */
    const uint32_t *state2;  /* 6 n_pair bits */
    uint32_t n_spair;
    const float *sstate2, *sforce2; /* 6 n_spair each */
    const int32_t *sstatus;
    const uint32_t *sout;    /* n_spair x 3 n_out bits */
} region_case;

static inline void region_fail(const char *what)
{
    fprintf(stderr, "region bundle: %s\n", what);
    exit(2);
}

static inline const uint32_t *region_words(region_reader *r, size_t n)
{
    if (r->pos + 4 * n > r->size) {
        region_fail("truncated");
    }
    const uint32_t *w = (const uint32_t *)(const void *)(r->data + r->pos);
    r->pos += 4 * n;
    return w;
}

static inline uint32_t region_get(region_reader *r)
{
    return *region_words(r, 1);
}

static inline void region_open(region_reader *r, const char *path, uint32_t *n_regions)
{
    const uint32_t one = 1;
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        perror(path);
        exit(2);
    }
    fseek(f, 0, SEEK_END);
    r->size = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    r->data = malloc(r->size);
    r->pos = 0;
    if (r->data == NULL || fread(r->data, 1, r->size, f) != r->size) {
        region_fail("cannot read");
    }
    fclose(f);
    if (*(const unsigned char *)&one != 1 || region_get(r) != TF_REGION_BUNDLE_MAGIC) {
        region_fail("not a region bundle (or a big-endian host)");
    }
    *n_regions = region_get(r);
}

static inline void region_read_model(region_reader *r, region_model *rm)
{
    tfit_model *m = &rm->m;
    m->api_version = TFIT_API_VERSION;
    m->family = region_get(r);
    m->n_out = region_get(r);
    m->n_dims = region_get(r);
    m->n_coef = region_get(r);
    m->dims = region_words(r, m->n_dims);
    m->coef = (const float *)(const void *)region_words(r, m->n_coef);
    m->node_ids = region_words(r, m->n_out);
    m->dims_end = m->dims + m->n_dims;
    m->coef_end = m->coef + m->n_coef;
    m->node_ids_end = m->node_ids + m->n_out;
    for (int k = 0; k < TFIT_CHECK_WORDS; ++k) {
        m->check[k] = region_get(r);
    }
    m->crc32 = region_get(r);
    rm->g.model = m;
    rm->g.n_vec = region_get(r);
    rm->g.in = region_words(r, 3 * (size_t)rm->g.n_vec);
    rm->g.status = (const int32_t *)(const void *)region_words(r, rm->g.n_vec);
    rm->g.out = region_words(r, (size_t)rm->g.n_vec * 3 * m->n_out);
}

static inline void region_read_case(region_reader *r, region_case *c)
{
    region_read_model(r, &c->law);
    region_read_model(r, &c->surf);
    c->law.g.model = &c->law.m; /* the structs moved into *c */
    c->surf.g.model = &c->surf.m;
    c->n_pair = region_get(r);
    c->tip2 = (const float *)(const void *)region_words(r, 6 * (size_t)c->n_pair);
    c->pstatus = (const int32_t *)(const void *)region_words(r, c->n_pair);
    c->force2 = region_words(r, 6 * (size_t)c->n_pair);
    c->state2 = region_words(r, 6 * (size_t)c->n_pair);
    c->n_spair = region_get(r);
    c->sstate2 = (const float *)(const void *)region_words(r, 6 * (size_t)c->n_spair);
    c->sforce2 = (const float *)(const void *)region_words(r, 6 * (size_t)c->n_spair);
    c->sstatus = (const int32_t *)(const void *)region_words(r, c->n_spair);
    c->sout = region_words(r, (size_t)c->n_spair * 3 * c->surf.m.n_out);
}

#endif /* TF_REGION_READ_H */
