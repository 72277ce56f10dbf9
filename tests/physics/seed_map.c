/*
 * seed_map.c — the shipped block48 header keeps the seed's meaning (issue 14):
 *
 *   seed_map SEED_SCENE          (compiled against one block48.h: -DHEADER)
 *
 * coeffs/block48.yaml is solved on a graded cloud and names its sites by
 * position; the seed grid (GUIDE §5, SEED_SCENE) names them by node number.
 * Firmware and tests that read output j as "the seed's node node_ids[j]"
 * must stay right, so this checks, from the compiled header's own tables:
 *   - the forward model has the seed scene's output count, and output j's
 *     node id is the seed scene's output j (same order);
 *   - the header's point j (TFIT_BLOCK48_OUTPUT_POINTS_MM) is where the seed
 *     grid's node node_ids[j] is, to float precision;
 *   - the contact point is the seed's contact node (61, the top centre),
 *     and the contact model's id is that node's number.
 * Exit 1 naming the first output that disagrees.
 */
#include <math.h>
#include <stdio.h>

#include "scene/scene.h"

#define TFIT_BLOCK48_IMPLEMENTATION
#include HEADER

/* float literals of 4.8 k are within half an ulp of 48 (2^-19 mm) */
#define TOL_MM 1e-5

static int same_point(const double *x, const float *y)
{
    return fabs(x[0] - y[0]) <= TOL_MM && fabs(x[1] - y[1]) <= TOL_MM && fabs(x[2] - y[2]) <= TOL_MM;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: seed_map SEED_SCENE\n");
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load(&ctx, argv[1], NULL, 0);
    if (s == NULL) {
        fprintf(stderr, "seed_map: %s\n", ctx.err);
        return 2;
    }
    const tf_problem *p = &s->problem;
    static const float pts[TFIT_BLOCK48_OUTPUT_POINTS_N][3] = TFIT_BLOCK48_OUTPUT_POINTS_MM;
    static const float contact[3] = TFIT_BLOCK48_CONTACT_POINT_MM;
    const tfit_model *m = &tfit_block48_forward;
    int bad = 0;
    if (m->n_out != TFIT_BLOCK48_OUTPUT_POINTS_N || m->n_out != p->outputs.n_nodes) {
        fprintf(stderr, "seed_map: the header has %u outputs and %u points, the seed scene %zu outputs\n",
                (unsigned)m->n_out, (unsigned)TFIT_BLOCK48_OUTPUT_POINTS_N, p->outputs.n_nodes);
        bad = 1;
    }
    for (uint32_t j = 0; !bad && j < m->n_out; ++j) {
        const uint32_t id = m->node_ids[j];
        if (id < 1 || id > p->cloud.n || p->outputs.nodes[j] != id - 1) {
            fprintf(stderr, "seed_map: output %u has node id %u, the seed scene's output %u is node %u\n",
                    (unsigned)j, (unsigned)id, (unsigned)j, (unsigned)p->outputs.nodes[j] + 1);
            bad = 1;
        } else if (!same_point(p->cloud.xyz + 3 * (size_t)(id - 1), pts[j])) {
            const double *x = p->cloud.xyz + 3 * (size_t)(id - 1);
            fprintf(stderr, "seed_map: output %u (node id %u) is at (%g, %g, %g) mm, the seed's node %u at "
                            "(%g, %g, %g) mm\n", (unsigned)j, (unsigned)id, (double)pts[j][0],
                    (double)pts[j][1], (double)pts[j][2], (unsigned)id, x[0], x[1], x[2]);
            bad = 1;
        }
    }
    const tf_contact *ct = &p->contacts[0];
    if (!bad && !(ct->by_node && same_point(p->cloud.xyz + 3 * (size_t)ct->node, contact))) {
        fprintf(stderr, "seed_map: the contact point (%g, %g, %g) mm is not the seed's contact node %u\n",
                (double)contact[0], (double)contact[1], (double)contact[2], (unsigned)ct->node + 1);
        bad = 1;
    }
    /* firmware finds the contact among the outputs by this id (haptic_loop.c) */
    if (!bad && tfit_block48_contact.node_ids[0] != ct->node + 1) {
        fprintf(stderr, "seed_map: the contact model's node id is %u, the seed's contact node %u\n",
                (unsigned)tfit_block48_contact.node_ids[0], (unsigned)ct->node + 1);
        bad = 1;
    }
    if (!bad) {
        printf("%s: its %u outputs are the seed's nodes %u ... %u at their positions (within %g mm), "
               "its contact point and id the seed's node %u\n", HEADER, (unsigned)m->n_out,
               (unsigned)m->node_ids[0], (unsigned)m->node_ids[m->n_out - 1], TOL_MM,
               (unsigned)ct->node + 1);
    }
    tf_scene_free(s);
    return bad;
}
