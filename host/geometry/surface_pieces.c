/*
 * surface_pieces.c — connected pieces by union-find over vertices
 * (surface_pieces.h).
 */
#include "geometry/surface_pieces.h"

#include <stdint.h>
#include <stdlib.h>

/* Root of v, halving the path on the way (iterative: no recursion). */
static size_t root(size_t *parent, size_t v)
{
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

int tf_surface_pieces(const tf_surface *s, size_t *piece, size_t *npieces)
{
    size_t *parent = malloc((s->nv + 1) * sizeof *parent);
    size_t *label = malloc((s->nv + 1) * sizeof *label);
    if (parent == NULL || label == NULL) {
        free(parent);
        free(label);
        return -1;
    }
    for (size_t v = 0; v < s->nv; ++v) {
        parent[v] = v;
        label[v] = SIZE_MAX;
    }
    for (size_t t = 0; t < s->nt; ++t) {
        size_t a = root(parent, s->tri[3 * t]);
        for (int k = 1; k < 3; ++k) {
            size_t b = root(parent, s->tri[3 * t + k]);
            if (a != b) {
                parent[b] = a;
            }
        }
    }
    size_t n = 0;
    for (size_t t = 0; t < s->nt; ++t) {
        size_t r = root(parent, s->tri[3 * t]);
        if (label[r] == SIZE_MAX) {
            label[r] = n++;
        }
        piece[t] = label[r];
    }
    *npieces = n;
    free(parent);
    free(label);
    return 0;
}
