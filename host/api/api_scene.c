/*
 * api_scene.c — scenes through the API (api.h): read as `tissuefit` reads
 * them (cli/cmd_args.c, the --set overrides), and what the Python side
 * needs to know of them.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_internal.h"
#include "cli/cmd_args.h"
#include "problem/inclusions.h"

tf_api_scene *tf_api_scene_load(tf_ctx *ctx, const char *path, const char *const *sets,
                                size_t n_sets)
{
    tf_sets list = {0};
    for (size_t i = 0; i < n_sets; ++i) {
        if (tf_sets_add(&list, sets[i]) != 0) {
            tf_sets_free(&list);
            tf_fail(ctx, "out of memory");
            return NULL;
        }
    }
    tf_api_scene *s = calloc(1, sizeof *s);
    char *name = strdup(path);
    ctx->err[0] = '\0';
    tf_scene *sc = s && name ? tf_cmd_scene(ctx, path, &list) : NULL;
    tf_sets_free(&list);
    size_t nc = sc ? sc->problem.n_cuts : 0;
    tf_cut *cuts = sc ? malloc((nc + 1) * sizeof *cuts) : NULL;
    if (cuts == NULL) {
        if (s == NULL || name == NULL || sc != NULL) {
            tf_fail(ctx, "out of memory");
        }
        tf_scene_free(sc);
        free(s);
        free(name);
        return NULL;
    }
    if (nc > 0) {
        memcpy(cuts, sc->problem.cuts, nc * sizeof *cuts);
    }
    *s = (tf_api_scene){.scene = sc, .path = name, .cuts = cuts, .n_cuts = nc, .progress = NAN};
    return s;
}

void tf_api_scene_free(tf_api_scene *s)
{
    if (s != NULL) {
        tf_solver_destroy(s->solver);
        tf_scene_free(s->scene);
        free(s->path);
        free(s->cuts);
        free(s);
    }
}

size_t tf_api_scene_nodes(const tf_api_scene *s, const double **xyz)
{
    if (xyz != NULL) {
        *xyz = s->scene->problem.cloud.xyz;
    }
    return s->scene->problem.cloud.n;
}

/* Positions and ids as report/displacement_out.c writes them. */
size_t tf_api_scene_outputs(const tf_api_scene *s, double *xyz, uint64_t *id)
{
    const tf_problem *p = &s->scene->problem;
    const tf_outputs *o = &p->outputs;
    for (size_t j = 0; xyz != NULL && j < o->n_nodes; ++j) {
        const double *x = o->points ? o->points + 3 * j : p->cloud.xyz + 3 * (size_t)o->nodes[j];
        memcpy(xyz + 3 * j, x, 3 * sizeof *xyz);
        if (id != NULL) {
            id[j] = o->points ? j + 1 : (uint64_t)o->nodes[j] + 1;
        }
    }
    return o->n_nodes;
}

size_t tf_api_scene_regions(const tf_api_scene *s, uint32_t *region)
{
    const tf_problem *p = &s->scene->problem;
    for (size_t i = 0; region != NULL && i < p->cloud.n; ++i) {
        region[i] = (uint32_t)tf_problem_region_at(p, p->cloud.xyz + 3 * i);
    }
    return p->n_inclusions;
}

size_t tf_api_scene_contacts(const tf_api_scene *s)
{
    return s->scene->problem.n_contacts;
}

const char *tf_api_scene_contact_name(const tf_api_scene *s, size_t k)
{
    return k < s->scene->problem.n_contacts ? s->scene->problem.contacts[k].name : NULL;
}
