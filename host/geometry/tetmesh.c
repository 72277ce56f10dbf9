/*
 * tetmesh.c — node cloud with tetrahedral cells: storage and volumes
 * (tetmesh.h).
 */
#include "geometry/tetmesh.h"

#include <stdlib.h>
#include <string.h>

#include "geometry/vec3.h"

void tf_tetmesh_free(tf_tetmesh *t)
{
    free(t->xyz);
    free(t->source);
    free(t->tet);
    free(t->tet_volume);
    free(t->tri);
    free(t->tri_parent);
    memset(t, 0, sizeof *t);
}

double tf_tet_volume(const double a[3], const double b[3], const double c[3], const double d[3])
{
    return tf_v3_orient(a, b, c, d) / 6;
}

void tf_tetmesh_volumes(tf_tetmesh *t)
{
    double sum = 0;
    for (size_t e = 0; e < t->ntet; ++e) {
        const size_t *v = t->tet + 4 * e;
        t->tet_volume[e] = tf_tet_volume(t->xyz + 3 * v[0], t->xyz + 3 * v[1], t->xyz + 3 * v[2],
                                         t->xyz + 3 * v[3]);
        sum += t->tet_volume[e];
    }
    t->cells_volume = sum;
}
