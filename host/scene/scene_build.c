/*
 * scene_build.c — defaults, checks and resolution of a scene document
 * (scene_build.h).  Every check names the path of the value at fault.
 */
#include "scene/scene_build.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitting/families/family.h"
#include "problem/regions.h"
#include "scene/scene_contact_region.h"
#include "scene/scene_cut_check.h"
#include "scene/scene_grading.h"
#include "scene/scene_held.h"
#include "scene/scene_history.h"
#include "scene/scene_material.h"
#include "scene/scene_organ.h"
#include "scene/scene_regions.h"
#include "solvers/collocation/colloc_solver.h"
#include "solvers/solver.h"

#define fail sd_fail

/* "prefix.k.key" into buf. */
static const char *at(char *buf, size_t len, const char *prefix, size_t k, const char *key)
{
    if (key != NULL) {
        snprintf(buf, len, "%s.%zu.%s", prefix, k, key);
    } else {
        snprintf(buf, len, "%s.%zu", prefix, k);
    }
    return buf;
}

static int finite_all(const double *v, size_t n)
{
    for (size_t k = 0; k < n; ++k) {
        if (!isfinite(v[k])) {
            return 0;
        }
    }
    return 1;
}

static int check_box(const sd_box *b, const char *path, sd_issue *is)
{
    if (!finite_all(b->min, 3) || !finite_all(b->max, 3)) {
        return sd_fail(is, path, "coordinates must be finite numbers");
    }
    for (int a = 0; a < 3; ++a) {
        if (!(b->min[a] < b->max[a])) {
            return sd_fail(is, path, "min must be below max along %c (%g >= %g)", "xyz"[a],
                        b->min[a], b->max[a]);
        }
    }
    return 0;
}

static int geometry(const sd_scene *doc, tf_problem *s, sd_issue *is)
{
    const sd_geometry *g = &doc->geometry;
    if ((g->box != NULL) == (g->surface != NULL)) {
        return sd_fail(is, "geometry",
                       "give exactly one of box (with grid) or surface (with spacing)");
    }
    if (g->surface) {
        return sd_organ_geometry(doc, s, is);
    }
    if (g->grid == NULL || g->spacing || g->refine || g->refine_skin) {
        return sd_fail(is, "geometry", "a box takes grid (and grading, jitter, seed), not spacing, "
                                       "refine or refine_skin");
    }
    if (check_box(g->box, "geometry.box", is) != 0) {
        return -1;
    }
    s->geometry.kind = TF_GEOMETRY_BOX;
    tf_box_geometry *box = &s->geometry.as.box;
    double nodes = 1;
    for (int a = 0; a < 3; ++a) {
        box->min[a] = g->box->min[a];
        box->max[a] = g->box->max[a];
        box->grid[a] = g->grid[a];
        if (g->grid[a] < 2) {
            return sd_fail(is, "geometry.grid", "at least 2 nodes per axis (got %u along %c)",
                        g->grid[a], "xyz"[a]);
        }
        nodes *= g->grid[a];
    }
    if (nodes > 2e6) {
        return sd_fail(is, "geometry.grid", "%.0f nodes is more than the 2 million this tool solves",
                    nodes);
    }
    box->jitter = g->jitter ? *g->jitter : 0;
    box->seed = g->seed ? *g->seed : 1;
    if (!(box->jitter >= 0 && box->jitter <= 0.4)) {
        return sd_fail(is, "geometry.jitter", "must be in [0, 0.4] (a fraction of the spacing)");
    }
    if (sd_grading(doc, box->min, box->max, &box->grading, is->msg, sizeof is->msg) != 0) {
        snprintf(is->path, sizeof is->path, "geometry.grading");
        return -1;
    }
    if (tf_cloud_box_graded(&s->cloud, box->min, box->max, box->grid, box->jitter, box->seed,
                            &box->grading) != 0) {
        return sd_fail(is, "geometry.grid", "out of memory for %.0f nodes", nodes);
    }
    return 0;
}

/* The regions of organs: a ball, a half-space, surface vertices near a
 * point (also usable on a box except `near`). */
static int shaped_region(const sd_fixed *d, size_t k, const tf_problem *s, tf_region *r,
                         sd_issue *is)
{
    char p[128];
    if (d->sphere) {
        r->kind = TF_REGION_SPHERE;
        memcpy(r->centre, d->sphere->centre, sizeof r->centre);
        r->radius = d->sphere->radius;
    } else if (d->side) {
        r->kind = TF_REGION_SIDE;
        memcpy(r->centre, d->side->point, sizeof r->centre);
        memcpy(r->normal, d->side->normal, sizeof r->normal);
        if (!finite_all(r->normal, 3) ||
            (r->normal[0] == 0 && r->normal[1] == 0 && r->normal[2] == 0)) {
            return fail(is, at(p, sizeof p, "fixed", k, "side"),
                        "the normal must be a finite non-zero vector");
        }
    } else {
        r->kind = TF_REGION_NEAR;
        memcpy(r->centre, d->near->point, sizeof r->centre);
        r->radius = d->near->distance;
        if (tf_problem_mesh(s) == NULL) {
            return fail(is, at(p, sizeof p, "fixed", k, "near"),
                        "near selects surface vertices of an organ (geometry.surface)");
        }
    }
    if (!finite_all(r->centre, 3) || !(isfinite(r->radius) && r->radius >= 0)) {
        return fail(is, at(p, sizeof p, "fixed", k, NULL),
                    "needs a finite point (mm) and a finite non-negative radius or distance");
    }
    return 0;
}

static int vertex_list(const sd_fixed *d, size_t k, const tf_problem *s, tf_fixed *f,
                       sd_issue *is)
{
    char p[128];
    f->where.kind = TF_REGION_VERTICES;
    f->n_nodes = d->vertices_count;
    f->nodes = malloc((f->n_nodes + 1) * sizeof *f->nodes);
    if (f->nodes == NULL) {
        return fail(is, at(p, sizeof p, "fixed", k, NULL), "out of memory");
    }
    return sd_organ_vertices(d->vertices, d->vertices_count, s,
                             at(p, sizeof p, "fixed", k, "vertices"), f->nodes, is);
}

static int fixed_one(const sd_fixed *d, size_t k, tf_problem *s, tf_fixed *f, sd_issue *is)
{
    char p[128];
    int kinds = (d->face != NULL) + (d->plane != NULL) + (d->box != NULL) +
                (d->sphere != NULL) + (d->side != NULL) + (d->near != NULL) +
                (d->vertices_count > 0);
    if (kinds != 1) {
        return sd_fail(is, at(p, sizeof p, "fixed", k, NULL),
                       "give exactly one of face, plane, box, sphere, side, near or vertices "
                       "(got %d)",
                       kinds);
    }
    if (d->face && tf_problem_mesh(s) != NULL) {
        return fail(is, at(p, sizeof p, "fixed", k, "face"),
                    "an organ has no box faces: use box, sphere, side, near or vertices");
    }
    if (d->sphere || d->side || d->near) {
        if (shaped_region(d, k, s, &f->where, is) != 0) {
            return -1;
        }
    } else if (d->vertices_count > 0) {
        if (vertex_list(d, k, s, f, is) != 0) {
            return -1;
        }
    } else if (d->face) {
        f->where.kind = TF_REGION_FACE;
        f->where.face = (tf_face)*d->face;
    } else if (d->plane) {
        f->where.kind = TF_REGION_PLANE;
        f->where.axis = d->plane->axis;
        f->where.at = d->plane->at;
        if (!isfinite(d->plane->at)) {
            return sd_fail(is, at(p, sizeof p, "fixed", k, "plane"), "'at' must be finite");
        }
    } else {
        f->where.kind = TF_REGION_BOX;
        if (check_box(d->box, at(p, sizeof p, "fixed", k, "box"), is) != 0) {
            return -1;
        }
        memcpy(f->where.min, d->box->min, sizeof f->where.min);
        memcpy(f->where.max, d->box->max, sizeof f->where.max);
    }
    f->components = d->components ? *d->components : TF_COMP_ALL;
    if (f->components == 0) {
        return sd_fail(is, at(p, sizeof p, "fixed", k, "components"), "names no component");
    }
    f->exact = d->exact && *d->exact;
    if (f->exact && d->displacement) {
        return sd_fail(is, at(p, sizeof p, "fixed", k, NULL),
                    "give displacement or exact: true, not both");
    }
    if (f->exact && s->analytic.kind == TF_ANALYTIC_NONE) {
        return sd_fail(is, at(p, sizeof p, "fixed", k, "exact"),
                    "exact: true needs a reference section");
    }
    for (int a = 0; a < 3; ++a) {
        f->value[a] = d->displacement ? d->displacement[a] : 0;
    }
    if (!finite_all(f->value, 3)) {
        return sd_fail(is, at(p, sizeof p, "fixed", k, "displacement"), "must be finite (mm)");
    }
    if (f->where.kind != TF_REGION_VERTICES &&
        tf_region_nodes(&s->cloud, &f->where, &f->nodes, &f->n_nodes) != 0) {
        return sd_fail(is, at(p, sizeof p, "fixed", k, NULL), "out of memory");
    }
    if (f->n_nodes == 0) {
        char where[320];
        sd_body_extent(s, where, sizeof where);
        return sd_fail(is, at(p, sizeof p, "fixed", k, NULL), "this region holds no node; %s",
                       where);
    }
    return 0;
}

/* Material regions: a sphere or a box each, linear elastic (inclusions.h). */
static int inclusions(const sd_scene *doc, tf_problem *s, sd_issue *is)
{
    char p[128];
    for (unsigned k = 0; k < doc->inclusions_count; ++k) {
        const sd_inclusion *d = &doc->inclusions[k];
        tf_inclusion *inc = &s->inclusions[k];
        if ((d->sphere != NULL) + (d->ellipsoid != NULL) + (d->box != NULL) != 1) {
            return sd_fail(is, at(p, sizeof p, "inclusions", k, NULL),
                           "give exactly one of sphere, ellipsoid or box");
        }
        snprintf(inc->name, sizeof inc->name, "%s", d->name ? d->name : "");
        if (d->sphere || d->ellipsoid) {
            inc->where.kind = TF_REGION_SPHERE;
            memcpy(inc->where.centre, d->sphere ? d->sphere->centre : d->ellipsoid->centre,
                   sizeof inc->where.centre);
            for (int a = 0; a < 3; ++a) {
                inc->radii[a] = d->sphere ? d->sphere->radius : d->ellipsoid->radii[a];
            }
            inc->where.radius = d->sphere ? d->sphere->radius : 0;
            const int ok = finite_all(inc->where.centre, 3) && finite_all(inc->radii, 3) &&
                           inc->radii[0] > 0 && inc->radii[1] > 0 && inc->radii[2] > 0;
            if (!ok) {
                return sd_fail(is, at(p, sizeof p, "inclusions", k, d->sphere ? "sphere" : "ellipsoid"),
                               "the centre must be finite and the %s",
                               d->sphere ? "radius a positive number of mm"
                                         : "radii positive numbers of mm");
            }
        } else {
            inc->where.kind = TF_REGION_BOX;
            if (check_box(d->box, at(p, sizeof p, "inclusions", k, "box"), is) != 0) {
                return -1;
            }
            memcpy(inc->where.min, d->box->min, sizeof inc->where.min);
            memcpy(inc->where.max, d->box->max, sizeof inc->where.max);
        }
        if (sd_build_material(&d->material, at(p, sizeof p, "inclusions", k, "material"),
                              &inc->material, is) != 0) {
            return -1;
        }
        s->n_inclusions = k + 1;
    }
    /* what the solvers take (tf_material_region_misfit): the body's law with
     * its own parameters (solvers/cell_stiffness.h for the linear law), or
     * another law of the same kinematics and volume measure in a body the
     * Newton solvers take (their per-point materials, nl_model.c) */
    for (size_t k = 0; k < s->n_inclusions; ++k) {
        const tf_material *m = &s->inclusions[k].material;
        const char *why = tf_material_region_misfit(&s->material, m);
        if (why != NULL) {
            return sd_fail(is, at(p, sizeof p, "inclusions", k, "material.law"),
                           "not yet: a region of the %s law in a body of the %s law: %s",
                           tf_material_name(m),
                           tf_material_name(&s->material), why);
        }
    }
    return 0;
}

static int fixed(const sd_scene *doc, tf_problem *s, sd_issue *is)
{
    s->fixed = calloc(doc->fixed_count, sizeof *s->fixed);
    if (s->fixed == NULL) {
        return sd_fail(is, "fixed", "out of memory");
    }
    s->n_fixed = doc->fixed_count;
    for (size_t k = 0; k < doc->fixed_count; ++k) {
        if (fixed_one(&doc->fixed[k], k, s, &s->fixed[k], is) != 0) {
            return -1;
        }
    }
    return 0;
}

static int node_index(uint32_t number, const tf_problem *s, const char *path, uint32_t *index,
                      sd_issue *is)
{
    if (number < 1 || number > s->cloud.n) {
        return sd_fail(is, path, "node %u does not exist (nodes are numbered 1 to %zu)", number,
                    s->cloud.n);
    }
    *index = number - 1;
    return 0;
}

/* A position given in the scene: finite and inside the body. */
static int position(const double *x, const tf_problem *s, const char *path, double out[3],
                    sd_issue *is)
{
    double tol = tf_cloud_tol(&s->cloud);
    if (!finite_all(x, 3)) {
        return sd_fail(is, path, "must be three finite coordinates (mm)");
    }
    for (int a = 0; a < 3; ++a) {
        if (x[a] < s->cloud.lo[a] - tol || x[a] > s->cloud.hi[a] + tol) {
            return sd_fail(is, path, "(%g, %g, %g) mm lies outside the body (%c in [%g, %g])", x[0],
                        x[1], x[2], "xyz"[a], s->cloud.lo[a], s->cloud.hi[a]);
        }
        out[a] = x[a];
    }
    return 0;
}

static int loads(const sd_scene *doc, tf_problem *s, sd_issue *is)
{
    char p[128];
    s->loads = calloc(doc->loads_count + 1, sizeof *s->loads);
    if (s->loads == NULL) {
        return sd_fail(is, "loads", "out of memory");
    }
    s->n_loads = doc->loads_count;
    for (size_t k = 0; k < doc->loads_count; ++k) {
        const sd_load *d = &doc->loads[k];
        tf_load *l = &s->loads[k];
        l->exact = d->exact && *d->exact;
        if ((d->node != NULL) + (d->at != NULL) + (d->patch != NULL) + (d->site != NULL) != 1) {
            return sd_fail(is, at(p, sizeof p, "loads", k, NULL),
                           "give exactly one of node, at, patch or site");
        }
        if (l->exact == (d->force != NULL)) {
            return sd_fail(is, at(p, sizeof p, "loads", k, NULL),
                        "give exactly one of force or exact: true");
        }
        if (l->exact && (s->analytic.kind == TF_ANALYTIC_NONE || d->patch == NULL)) {
            return sd_fail(is, at(p, sizeof p, "loads", k, "exact"),
                        "exact: true needs a reference section and a patch");
        }
        if (d->force) {
            memcpy(l->force, d->force, sizeof l->force);
            if (!finite_all(l->force, 3)) {
                return sd_fail(is, at(p, sizeof p, "loads", k, "force"), "must be finite (N)");
            }
        }
        if (d->site) {
            uint32_t node;
            if (sd_organ_site(d->site, s, at(p, sizeof p, "loads", k, NULL), &l->patch, &node,
                              is) != 0) {
                return -1;
            }
        } else if (d->node) {
            l->patch.shape = TF_PATCH_POINT;
            if (node_index(*d->node, s, at(p, sizeof p, "loads", k, "node"), &l->patch.node, is)) {
                return -1;
            }
        } else if (d->at) {
            l->patch.shape = TF_PATCH_AT;
            if (position(d->at, s, at(p, sizeof p, "loads", k, "at"), l->patch.at, is) != 0) {
                return -1;
            }
        } else if (sd_resolve_patch(d->patch, &s->cloud, &l->patch, is->msg, sizeof is->msg) != 0) {
            snprintf(is->path, sizeof is->path, "%s", at(p, sizeof p, "loads", k, "patch"));
            return -1;
        }
    }
    return 0;
}

/* Where a contact site is: a node number, a point, or its patch's centre;
 * and how its force is spread (its patch, else a point force there). */
static int contact_site(const sd_contact *d, const tf_problem *s, size_t k, tf_contact *c,
                        sd_issue *is)
{
    char p[128];
    int forms = (d->node != NULL) + (d->at != NULL);
    if (forms > 1 || (forms == 0 && d->patch == NULL)) {
        return sd_fail(is, at(p, sizeof p, "contact", k, NULL),
                    "give the contact point as one of node or at (or neither, with a patch: "
                    "its centre)");
    }
    if (d->patch && sd_resolve_patch(d->patch, &s->cloud, &c->patch, is->msg, sizeof is->msg) != 0) {
        snprintf(is->path, sizeof is->path, "%s", at(p, sizeof p, "contact", k, "patch"));
        return -1;
    }
    c->by_node = d->node != NULL;
    if (d->node) {
        if (node_index(*d->node, s, at(p, sizeof p, "contact", k, "node"), &c->node, is) != 0) {
            return -1;
        }
        memcpy(c->at, s->cloud.xyz + 3 * (size_t)c->node, sizeof c->at);
    } else if (d->at) {
        if (position(d->at, s, at(p, sizeof p, "contact", k, "at"), c->at, is) != 0) {
            return -1;
        }
        c->node = tf_problem_nearest_node(s, c->at);
    } else {
        tf_problem_patch_centre(&c->patch, &s->cloud, c->at);
        c->node = tf_problem_nearest_node(s, c->at);
    }
    if (d->patch == NULL) {
        c->patch.shape = c->by_node ? TF_PATCH_POINT : TF_PATCH_AT;
        c->patch.node = c->node;
        memcpy(c->patch.at, c->at, sizeof c->at);
    }
    return 0;
}

static int contacts(const sd_scene *doc, tf_problem *s, sd_issue *is)
{
    char p[128];
    s->contacts = calloc(doc->contact_count + 1, sizeof *s->contacts);
    if (s->contacts == NULL) {
        return sd_fail(is, "contact", "out of memory");
    }
    s->n_contacts = doc->contact_count;
    for (size_t k = 0; k < doc->contact_count; ++k) {
        const sd_contact *d = &doc->contact[k];
        tf_contact *c = &s->contacts[k];
        if (d->name) {
            snprintf(c->name, sizeof c->name, "%s", d->name);
        } else {
            snprintf(c->name, sizeof c->name, "contact%zu", k + 1);
        }
        for (size_t j = 0; j < k; ++j) {
            if (strcmp(s->contacts[j].name, c->name) == 0) {
                return sd_fail(is, at(p, sizeof p, "contact", k, "name"),
                            "'%s' names contact %zu already", c->name, j);
            }
        }
        if (sd_contact_is_region(d)) {
            if (sd_contact_region(doc, k, s, c, is) != 0) {
                return -1;
            }
            continue;
        }
        if (d->site && (d->node || d->at || d->patch)) {
            return sd_fail(is, at(p, sizeof p, "contact", k, NULL),
                           "give a site on an organ, or node, at or patch on a box, not both");
        }
        if (d->site) {
            /* The site's centre is the surface vertex nearest its point: a
             * node, so its nodal value is the contact displacement. */
            if (sd_organ_site(d->site, s, at(p, sizeof p, "contact", k, NULL), &c->patch,
                              &c->node, is) != 0) {
                return -1;
            }
            c->by_node = 1;
            memcpy(c->at, s->cloud.xyz + 3 * (size_t)c->node, sizeof c->at);
            continue;
        }
        if (contact_site(d, s, k, c, is) != 0) {
            return -1;
        }
    }
    return 0;
}

/* Incisions: each segment of non-zero length, every point on the top face
 * (inside the box's x, y extent, borders included), depth in (0, height]. */
/* Whether (x, y) lies inside the closed polygon c->xy[0..n) (even-odd). */
static int inside_cut(const tf_cut *c, double x, double y)
{
    int in = 0;
    for (size_t i = 0, j = c->n - 1; i < c->n; j = i++) {
        const double *a = c->xy[i], *b = c->xy[j];
        if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) {
            in = !in;
        }
    }
    return in;
}

/* A closed cut through the full height cuts a plug out of the block: it
 * must hold a fixed node, or the plug floats (its stiffness is singular
 * and a solve returned whatever the factorisation made of it).  Returns 0
 * or -1 with the message. */
static int plug_is_held(const tf_problem *s, size_t k, sd_issue *is)
{
    const tf_cut *c = &s->cuts[k];
    const double h = s->geometry.as.box.max[2] - s->geometry.as.box.min[2];
    if (c->n < 4 || c->xy[0][0] != c->xy[c->n - 1][0] || c->xy[0][1] != c->xy[c->n - 1][1] ||
        c->depth < h) {
        return 0;
    }
    unsigned char *fixed = malloc(3 * s->cloud.n + 1);
    if (fixed == NULL) {
        return sd_fail(is, "cuts", "out of memory");
    }
    tf_problem_fixed_dofs(s, fixed);
    size_t nodes = 0, held = 0;
    for (size_t i = 0; i < s->cloud.n; ++i) {
        const double *x = s->cloud.xyz + 3 * i;
        if (inside_cut(c, x[0], x[1])) {
            nodes++;
            held += fixed[3 * i] || fixed[3 * i + 1] || fixed[3 * i + 2];
        }
    }
    free(fixed);
    if (nodes > 0 && held == 0) {
        char p[64];
        return sd_fail(is, at(p, sizeof p, "cuts", k, "path"),
                       "a closed cut through the full height frees a plug of %zu nodes that no "
                       "fixed region holds (a shallower cut, an open path, or a fixed region "
                       "inside)",
                       nodes);
    }
    return 0;
}

/* Cut k repeats an earlier one (the same path and depth: it cut nothing
 * more, yet the visibility of the shape functions counted it twice). */
static int repeats(const tf_problem *s, size_t k, sd_issue *is)
{
    const tf_cut *c = &s->cuts[k];
    for (size_t j = 0; j < k; ++j) {
        const tf_cut *e = &s->cuts[j];
        if (e->n == c->n && e->depth == c->depth &&
            memcmp(e->xy, c->xy, c->n * sizeof c->xy[0]) == 0) {
            char p[64];
            return sd_fail(is, at(p, sizeof p, "cuts", k, "path"),
                           "repeats cuts.%zu (the same path and depth)", j);
        }
    }
    return 0;
}

static int cuts(const sd_scene *doc, tf_problem *s, sd_issue *is)
{
    if (doc->cuts_count > 0 && tf_problem_mesh(s) != NULL) {
        return sd_fail(is, "cuts", "a cut is swept down from a box's top face: an organ's mesh "
                                   "takes none");
    }
    const tf_box_geometry *b = &s->geometry.as.box;
    char p[128];
    s->cuts = calloc(doc->cuts_count + 1, sizeof *s->cuts);
    if (s->cuts == NULL) {
        return sd_fail(is, "cuts", "out of memory");
    }
    s->n_cuts = doc->cuts_count;
    for (size_t k = 0; k < doc->cuts_count; ++k) {
        const sd_cut *d = &doc->cuts[k];
        tf_cut *c = &s->cuts[k];
        double h = b->max[2] - b->min[2];
        if (!(d->depth > 0 && d->depth <= h)) {
            return sd_fail(is, at(p, sizeof p, "cuts", k, "depth"),
                        "the depth must lie in (0, %g] mm, the block's height (got %g)", h,
                        d->depth);
        }
        c->n = d->path_count;
        c->top = b->max[2];
        c->depth = d->depth;
        for (size_t i = 0; i < c->n; ++i) {
            for (int a = 0; a < 2; ++a) {
                c->xy[i][a] = d->path[i].v[a];
                if (!(c->xy[i][a] >= b->min[a] && c->xy[i][a] <= b->max[a])) {
                    snprintf(p, sizeof p, "cuts.%zu.path.%zu", k, i);
                    return sd_fail(is, p,
                                "point (%g, %g) lies outside the top face [%g, %g] x [%g, %g] mm",
                                d->path[i].v[0], d->path[i].v[1], b->min[0], b->max[0],
                                b->min[1], b->max[1]);
                }
            }
            if (i > 0 && c->xy[i][0] == c->xy[i - 1][0] && c->xy[i][1] == c->xy[i - 1][1]) {
                snprintf(p, sizeof p, "cuts.%zu.path.%zu", k, i);
                return sd_fail(is, p, "a segment of zero length (the point repeats the one before)");
            }
        }
        if (repeats(s, k, is) != 0 || plug_is_held(s, k, is) != 0) {
            return -1;
        }
    }
    return 0;
}

static int envelope(const sd_envelope *e, tf_problem *s, sd_issue *is)
{
    s->envelope.radius = e && e->radius ? *e->radius : 1.0;
    for (int a = 0; a < 3; ++a) {
        s->envelope.centre[a] = e && e->centre ? e->centre[a] : 0;
    }
    if (!(isfinite(s->envelope.radius) && s->envelope.radius > 0)) {
        return sd_fail(is, "envelope.radius", "must be a positive number of newtons");
    }
    if (!finite_all(s->envelope.centre, 3)) {
        return sd_fail(is, "envelope.centre", "must be finite (N)");
    }
    return 0;
}

/* The default multiquadric length: d_c relative to the local nodal spacing
 * (docs/validation.md, the shape-parameter study); 0 would make the seed's
 * absolute d_c = 2 mm the default. */
#define SD_D_C_SPACINGS 8.0

tf_solver_opts sd_solver_defaults(const unsigned grid[3])
{
    tf_solver_opts o = {
        .method = "rpim-galerkin",
        .support = 2.0,
        .centre = TF_SUPPORT_CELL,
        .alpha_c = 1.0,
        .d_c = 2.0,
        .d_c_spacings = SD_D_C_SPACINGS,
        .q = 1.03,
        .polynomial = 1,
        .volumetric = TF_VOLUMETRIC_CELL,
        .gauss = 3,
        .tet_degree = 2,
        .bc = TF_BC_ELIMINATION,
        .penalty = 1e7,
        .nitsche = 100,
        .integration = TF_INTEGRATION_GAUSS,
        .rcond_warn = 1e-12,
        .colloc = tf_colloc_settings_default(),
        .newton = {.rtol = 1e-9, .etol = 1e-18, .max_iter = 50, .steps = 1, .max_cuts = 10,
                   .tangent = TF_TANGENT_BFGS, .krylov_max = 100,
                   .patch_radius = 4, .indefinite = TF_INDEFINITE_LDL},
        .ordering = 0,
    };
    for (int a = 0; a < 3; ++a) {
        o.cells[a] = grid[a] - 1;
    }
    return o;
}

/* solver.collocation (the mls-collocation solver, docs/collocation.md). */
static int colloc(const sd_colloc *d, tf_colloc_settings *c, sd_issue *is)
{
    if (d == NULL) {
        return 0;
    }
    c->neighbours = d->neighbours ? *d->neighbours : c->neighbours;
    c->support = d->support ? *d->support : c->support;
    c->stabilisation = d->stabilisation ? *d->stabilisation : c->stabilisation;
    c->volume_constant = d->volume_constant ? *d->volume_constant : c->volume_constant;
    c->density = d->density ? *d->density : c->density;
    c->damping = d->damping ? *d->damping : c->damping;
    c->tolerance = d->tolerance ? *d->tolerance : c->tolerance;
    if (c->neighbours < 4 || c->neighbours > 256) {
        return sd_fail(is, "solver.collocation.neighbours", "4 to 256 nearest particles");
    }
    if (!(c->support > 1 && c->support <= 10)) {
        return sd_fail(is, "solver.collocation.support",
                       "the support radius must be 1 to 10 mean neighbour distances");
    }
    if (!(isfinite(c->stabilisation) && c->stabilisation >= 0)) {
        return sd_fail(is, "solver.collocation.stabilisation", "must be a number >= 0");
    }
    if (!(isfinite(c->volume_constant) && c->volume_constant >= 0)) {
        return sd_fail(is, "solver.collocation.volume_constant", "must be >= 0 (MPa)");
    }
    if (!(isfinite(c->density) && c->density > 0)) {
        return sd_fail(is, "solver.collocation.density", "must be > 0 (t/mm^3; water: 1e-9)");
    }
    if (!(isfinite(c->damping) && c->damping >= 0)) {
        return sd_fail(is, "solver.collocation.damping", "must be >= 0 (1/s)");
    }
    if (!(c->tolerance > 0 && c->tolerance < 1)) {
        return sd_fail(is, "solver.collocation.tolerance", "must lie in (0, 1)");
    }
    return 0;
}

static int newton(const sd_newton *d, tf_newton_opts *o, sd_issue *is)
{
    if (d == NULL) {
        return 0;
    }
    o->rtol = d->tolerance ? *d->tolerance : o->rtol;
    o->etol = d->energy_tolerance ? *d->energy_tolerance : o->etol;
    o->max_iter = d->iterations ? *d->iterations : o->max_iter;
    o->steps = d->steps ? *d->steps : o->steps;
    o->max_cuts = d->cuts ? *d->cuts : o->max_cuts;
    o->tangent = d->tangent ? (tf_tangent_kind)*d->tangent : o->tangent;
    o->krylov_max = d->krylov_iterations ? *d->krylov_iterations : o->krylov_max;
    o->patch_radius = d->patch_radius ? *d->patch_radius : o->patch_radius;
    o->indefinite = d->indefinite ? (tf_indefinite_kind)*d->indefinite : o->indefinite;
    if (!(o->rtol > 0 && o->rtol < 1)) {
        return sd_fail(is, "solver.newton.tolerance", "must lie in (0, 1)");
    }
    if (!(o->etol > 0 && o->etol < 1)) {
        return sd_fail(is, "solver.newton.energy_tolerance", "must lie in (0, 1)");
    }
    if (o->max_iter < 1 || o->max_iter > 1000) {
        return sd_fail(is, "solver.newton.iterations", "1 to 1000 iterations per load step");
    }
    if (o->steps < 1 || o->steps > 100000) {
        return sd_fail(is, "solver.newton.steps", "1 to 100000 load steps to begin with");
    }
    if (o->max_cuts > 30) {
        return sd_fail(is, "solver.newton.cuts", "0 to 30 halvings of a load step");
    }
    if (o->krylov_max < 1 || o->krylov_max > 10000) {
        return sd_fail(is, "solver.newton.krylov_iterations", "1 to 10000 iterations");
    }
    if (!(o->patch_radius > 0 && o->patch_radius < 1e6)) {
        return sd_fail(is, "solver.newton.patch_radius", "must be a positive length in mm");
    }
    return 0;
}

static int solver(const sd_solver *d, tf_problem *s, sd_issue *is)
{
    tf_solver_opts *o = &s->solver;
    static const unsigned no_grid[3] = {2, 2, 2}; /* an organ has no background grid */
    *o = sd_solver_defaults(s->geometry.kind == TF_GEOMETRY_BOX ? s->geometry.as.box.grid
                                                                : no_grid);
    if (s->geometry.kind != TF_GEOMETRY_BOX) {
        /* An organ's default d_c is the seed's absolute 2 mm: its supports
         * (balls of up to 60 nodes, a dense skin) leave the relative 8 h
         * singular, 4 h ill-conditioned (docs/validation.md §14). */
        o->d_c_spacings = 0;
    }
    if (d == NULL) {
        return 0;
    }
    if (d->method) {
        if (tf_solver_type_find(d->method) == NULL) {
            char names[256];
            tf_solver_type_names(names, sizeof names);
            return sd_fail(is, "solver.method", "'%s' is not one of: %s", d->method, names);
        }
        snprintf(o->method, sizeof o->method, "%s", d->method);
    }
    o->support = d->support ? *d->support : o->support;
    o->centre = d->centre ? (tf_support_centre)*d->centre : o->centre;
    if (d->rbf) {
        if (d->rbf->d_c && d->rbf->spacings) {
            return sd_fail(is, "solver.rbf",
                        "give d_c (mm, absolute) or spacings (d_c relative to the local "
                        "nodal spacing), not both");
        }
        o->alpha_c = d->rbf->alpha_c ? *d->rbf->alpha_c : o->alpha_c;
        o->d_c = d->rbf->d_c ? *d->rbf->d_c : o->d_c;
        o->d_c_spacings = d->rbf->d_c ? 0 : d->rbf->spacings ? *d->rbf->spacings : o->d_c_spacings;
        o->q = d->rbf->q ? *d->rbf->q : o->q;
        if (d->rbf->spacings && !(isfinite(o->d_c_spacings) && o->d_c_spacings > 0)) {
            return sd_fail(is, "solver.rbf.spacings", "must be a positive number of nodal spacings");
        }
    }
    o->polynomial = d->polynomial ? *d->polynomial : o->polynomial;
    o->volumetric = d->volumetric ? (tf_volumetric)*d->volumetric : o->volumetric;
    for (int a = 0; d->cells && a < 3; ++a) {
        o->cells[a] = d->cells[a];
    }
    o->gauss = d->gauss ? *d->gauss : o->gauss;
    o->tet_degree = d->tet_degree ? *d->tet_degree : o->tet_degree;
    const tf_solver_ops *type = tf_solver_type_find(o->method);
    int weak = type != NULL && type->weak_bc; /* (an unknown method was refused above) */
    o->bc = d->bc ? (tf_bc_method)*d->bc : weak ? TF_BC_NITSCHE : o->bc;
    o->penalty = d->penalty ? *d->penalty : o->penalty;
    o->nitsche = d->nitsche ? *d->nitsche : o->nitsche;
    o->integration = d->integration ? (tf_integration)*d->integration : o->integration;
    o->ordering = d->ordering ? *d->ordering : o->ordering;
    if (newton(d->newton, &o->newton, is) != 0) {
        return -1;
    }
    o->rcond_warn = d->rcond_warn ? *d->rcond_warn : o->rcond_warn;
    if (!(isfinite(o->support) && o->support > 0)) {
        return sd_fail(is, "solver.support", "must be a positive number of nodal spacings");
    }
    if (!(isfinite(o->alpha_c) && o->alpha_c > 0)) {
        return sd_fail(is, "solver.rbf.alpha_c", "must be positive");
    }
    if (!(isfinite(o->d_c) && o->d_c > 0)) {
        return sd_fail(is, "solver.rbf.d_c", "must be a positive length (mm)");
    }
    if (!(isfinite(o->q) && o->q > 0) || o->q == floor(o->q)) {
        return sd_fail(is, "solver.rbf.q",
                    "must be positive and not a whole number (an integer q makes the "
                    "multiquadric a polynomial and the local systems singular)");
    }
    for (int a = 0; a < 3; ++a) {
        if (o->cells[a] < 1 || o->cells[a] > 4096) {
            return sd_fail(is, "solver.cells", "1 to 4096 background cells per axis");
        }
    }
    /* each cell's Gauss points hold their shape functions: 10^6 cells is
     * past what memory holds at any support (41 x 41 x 9 nodes use 12,800) */
    double cells = (double)o->cells[0] * o->cells[1] * o->cells[2];
    if (cells > TF_SOLVER_MAX_CELLS) {
        return sd_fail(is, "solver.cells", "%u x %u x %u = %.0f background cells, more than %d",
                       o->cells[0], o->cells[1], o->cells[2], cells, TF_SOLVER_MAX_CELLS);
    }
    if (o->gauss < 1 || o->gauss > 12) {
        return sd_fail(is, "solver.gauss", "1 to 12 Gauss points per axis");
    }
    if (o->tet_degree < 1 || o->tet_degree > 5) {
        return fail(is, "solver.tet_degree",
                    "1 to 5: the degree of the tetrahedron rule (1, 2 or 5 points sets; 3 and 4 "
                    "use the degree-5 rule)");
    }
    if (!(isfinite(o->penalty) && o->penalty > 0)) {
        return sd_fail(is, "solver.penalty", "must be a positive factor");
    }
    if (!(isfinite(o->nitsche) && o->nitsche > 0)) {
        return sd_fail(is, "solver.nitsche", "must be a positive factor");
    }
    if (weak && o->bc == TF_BC_ELIMINATION) {
        return sd_fail(is, "solver.bc",
                       "elimination needs shape functions that interpolate (rpim-galerkin); %s "
                       "takes penalty or nitsche",
                       o->method);
    }
    if (!(o->rcond_warn > 0 && o->rcond_warn < 1)) {
        return sd_fail(is, "solver.rcond_warn", "must lie in (0, 1)");
    }
    return colloc(d->collocation, &o->colloc, is);
}

static int reference(const sd_reference *d, tf_problem *s, sd_issue *is)
{
    tf_analytic *r = &s->analytic;
    r->kind = d ? (tf_analytic_kind)d->kind : TF_ANALYTIC_NONE;
    if (d == NULL) {
        return 0;
    }
    if (r->kind == TF_ANALYTIC_CANTILEVER) {
        if (d->load == NULL || !isfinite(*d->load) || d->offset || d->gradient) {
            return sd_fail(is, "reference", "cantilever takes a finite load (N/mm) and nothing else");
        }
        r->load = *d->load;
        return 0;
    }
    if (d->gradient == NULL || d->load) {
        return sd_fail(is, "reference", "linear takes a gradient (9 numbers), an optional offset");
    }
    memcpy(r->gradient, d->gradient, sizeof r->gradient);
    for (int a = 0; a < 3; ++a) {
        r->offset[a] = d->offset ? d->offset[a] : 0;
    }
    if (!finite_all(r->gradient, 9) || !finite_all(r->offset, 3)) {
        return sd_fail(is, "reference", "values must be finite");
    }
    return 0;
}

/* The fit: section's force histories (a time-dependent solver's; the
 * prony family's tick).  The tick is whole microseconds up to 1 s (the
 * model stores nanoseconds in 32 bits); whether it suits the fitted time
 * constants is the prony fit's check (docs/fitting.md §7.3). */
static int fit_histories(const sd_fit *d, tf_fit_plan *f, sd_issue *is)
{
    if (d->tick_us) {
        if (*d->tick_us < 1 || *d->tick_us > 1000000) {
            return sd_fail(is, "fit.tick_us", "1 to 1000000 microseconds");
        }
        f->tick_ns = 1000u * *d->tick_us;
    }
    f->hist_train = d->histories ? *d->histories : f->hist_train;
    f->hist_heldout = d->heldout_histories ? *d->heldout_histories : f->hist_heldout;
    f->hist_ticks = d->history_ticks ? *d->history_ticks : f->hist_ticks;
    if (f->hist_train < 2 || f->hist_train > 10000) {
        return sd_fail(is, "fit.histories", "2 to 10000 training force histories");
    }
    if (f->hist_heldout < 1 || f->hist_heldout > 10000) {
        return sd_fail(is, "fit.heldout_histories", "1 to 10000 held-out force histories");
    }
    if (f->hist_ticks < 10 || f->hist_ticks > 10000000) {
        return sd_fail(is, "fit.history_ticks", "10 to 10000000 ticks per history");
    }
    f->hist_solve_every = d->solve_every ? *d->solve_every : f->hist_solve_every;
    if (f->hist_solve_every < 1 || f->hist_solve_every > f->hist_ticks / 2) {
        return sd_fail(is, "fit.solve_every", "1 to half of history_ticks ticks per solver step");
    }
    return 0;
}

/* The fit: section's cut progress (the cut family, docs/cutting.md): the
 * largest number of intervals in s, a power of two up to the target's
 * TFIT_CUT_MAX_INTERVALS, on a scene with cuts. */
static int fit_cut(const sd_fit *d, const tf_problem *s, tf_fit_plan *f, sd_issue *is)
{
    if (d->cut_intervals) {
        const unsigned k = *d->cut_intervals;
        if (k < 1 || k > TFIT_CUT_MAX_INTERVALS || (k & (k - 1)) != 0) {
            return sd_fail(is, "fit.cut_intervals", "a power of two from 1 to %d (got %u)",
                           TFIT_CUT_MAX_INTERVALS, k);
        }
        if (s->n_cuts == 0) {
            return sd_fail(is, "fit.cut_intervals", "the scene has no cuts: to progress");
        }
        f->cut_intervals = k;
    }
    if (d->cut_heldout) {
        if (*d->cut_heldout < 1 || *d->cut_heldout > 100) {
            return sd_fail(is, "fit.cut_heldout", "1 to 100 held-out cut progress values");
        }
        if (!d->cut_intervals) {
            return sd_fail(is, "fit.cut_heldout", "needs fit.cut_intervals");
        }
        f->cut_heldout = *d->cut_heldout;
    }
    return 0;
}

/* The fit: section.  Limits keep every design matrix of a fold
 * non-trivial and the searches inside the target's capacity (tfit.h). */
static int fit(const sd_fit *d, const tf_problem *s, tf_fit_plan *f, sd_issue *is)
{
    tf_fit_plan_defaults(f);
    f->contact = s->n_contacts > 0 ? 0 : -1;
    if (d == NULL) {
        return 0;
    }
    if (d->family) {
        f->family = tf_family_find(d->family);
        f->family_asked = 1;
        if (f->family == NULL || f->family->kind != TF_FAMILY_FORWARD) {
            char names[256];
            tf_family_names(TF_FAMILY_FORWARD, names, sizeof names);
            return sd_fail(is, "fit.family", "'%s' is not one of the forward families: %s",
                        d->family, names);
        }
    }
    f->n_train = d->train ? *d->train : f->n_train;
    f->n_heldout = d->heldout ? *d->heldout : f->n_heldout;
    f->seed = d->seed ? *d->seed : f->seed;
    f->folds = d->folds ? *d->folds : f->folds;
    f->max_degree = d->max_degree ? *d->max_degree : f->max_degree;
    f->max_rank = d->max_rank ? *d->max_rank : f->max_rank;
    f->servo_hz = d->servo_hz ? *d->servo_hz : f->servo_hz;
    if (d->contact) {
        f->contact = tf_problem_contact(s, d->contact);
        if (f->contact < 0) {
            return sd_fail(is, "fit.contact", "names no contact site of the scene");
        }
    }
    if (f->n_train < 6 || f->n_train > 100000) {
        return sd_fail(is, "fit.train", "6 to 100000 training load cases");
    }
    if (f->n_heldout < 1 || f->n_heldout > 100000) {
        return sd_fail(is, "fit.heldout", "1 to 100000 held-out load cases");
    }
    if (f->folds < 2 || f->folds > 20 || f->folds > f->n_train) {
        return sd_fail(is, "fit.folds", "2 to 20 folds, and no more than the training cases");
    }
    if (f->max_degree > 8) {
        return sd_fail(is, "fit.max_degree", "0 to 8 (the target's TFIT_MAX_DEGREE)");
    }
    if (f->max_rank < 1 || f->max_rank > TF_FAMILY_MAX_RANK) {
        return sd_fail(is, "fit.max_rank", "1 to %d modes", TF_FAMILY_MAX_RANK);
    }
    if (d->servo_hz && (f->servo_hz < 1 || f->servo_hz > 100000)) {
        return sd_fail(is, "fit.servo_hz", "1 to 100000 Hz (the haptic loop's rate)");
    }
    return fit_histories(d, f, is) != 0 ? -1 : fit_cut(d, s, f, is);
}

int sd_build(const sd_scene *doc, tf_problem *s, tf_fit_plan *plan, sd_issue *is)
{
    if (doc->name) {
        snprintf(s->name, sizeof s->name, "%s", doc->name);
    }
    if (geometry(doc, s, is) != 0 ||
        sd_build_material(&doc->material, "material", &s->material, is) != 0 ||
        inclusions(doc, s, is) != 0 ||
        reference(doc->reference, s, is) != 0 || fixed(doc, s, is) != 0 ||
        sd_check_held(s, is) != 0 ||
        loads(doc, s, is) != 0 || contacts(doc, s, is) != 0 ||
        envelope(doc->envelope, s, is) != 0 || cuts(doc, s, is) != 0 ||
        solver(doc->solver, s, is) != 0 || sd_check_cuts(s, is) != 0 ||
        sd_history_build(doc->history, s, is) != 0 || fit(doc->fit, s, plan, is) != 0) {
        return -1;
    }
    if (sd_resolve_outputs(&doc->outputs, s, &s->outputs, is->msg, sizeof is->msg) != 0) {
        snprintf(is->path, sizeof is->path, "outputs");
        return -1;
    }
    return 0;
}
