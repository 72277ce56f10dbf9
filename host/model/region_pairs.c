/*
 * region_pairs.c — see region_pairs.h.
 */
#include "model/region_pairs.h"

#include <stdlib.h>
#include <string.h>

#include "model/region_ref.h"

int tf_region_pairs_affine(const tf_model *law, const tf_model *surf)
{
    return law->dims[2] == 2 && surf->dims[3] == 1 && surf->dims[4] == 1;
}

void tf_region_pairs_free(tf_region_pairs *p)
{
    free(p->sout);
    p->sout = NULL;
    p->n = p->ns = 0;
}

int tf_region_pairs_design(const tf_model *law, const tf_model *surf, uint64_t seed,
                           tf_region_pairs *p)
{
    float a[TF_GOLDEN_MAX][3], b[TF_GOLDEN_MAX][3];
    p->n = p->ns = 0;
    p->sout = NULL;
    if (surf->dims[3] == 1) {
        const size_t n = tf_golden_design(surf, seed, a);
        p->sout = malloc((n * 3 * surf->n_out + 1) * sizeof *p->sout);
        if (p->sout == NULL) {
            return -1;
        }
        for (size_t v = 0; v < n; ++v) {
            tf_region_ref_golden_state(surf, (uint32_t)v, p->sstate[v]);
            tf_region_ref_golden_state(surf, (uint32_t)v + 5, p->sstate[v] + 3);
            memcpy(p->sforce[v], a[v], sizeof a[v]);
            memcpy(p->sforce[v] + 3, a[(v + 11) % n], sizeof a[v]);
            p->sstatus[v] = (int32_t)tf_region_ref_surface_pair(
                surf, p->sstate[v], p->sforce[v], p->sout + v * 3 * surf->n_out);
        }
        p->ns = n;
    }
    if (!tf_region_pairs_affine(law, surf)) {
        return 0;
    }
    const size_t n = tf_golden_design(law, seed, a);
    tf_golden_design(law, seed + 1, b);
    float st[6];
    tf_region_ref_reset(st);
    tf_region_ref_reset(st + 3);
    for (size_t v = 0; v < n; ++v) {
        memcpy(p->tip[v], a[v], sizeof a[v]);
        memcpy(p->tip[v] + 3, b[(v + 7) % n], sizeof b[v]);
        p->status[v] = (int32_t)tf_region_ref_pair(law, surf, st, p->tip[v], p->force[v]);
        memcpy(p->state[v], st, sizeof st);
    }
    p->n = n;
    return 0;
}
