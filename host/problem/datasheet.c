/*
 * datasheet.c — see datasheet.h.
 */
#include "problem/datasheet.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

typedef struct sheet {
    char *buf;
    size_t n, len;
} sheet;

static void put(sheet *s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(sheet *s, const char *fmt, ...)
{
    if (s->len + 1 >= s->n) {
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(s->buf + s->len, s->n - s->len, fmt, ap);
    va_end(ap);
    if (k > 0) {
        s->len = s->len + (size_t)k < s->n ? s->len + (size_t)k : s->n - 1;
    }
}

static const char *face_name(tf_face f)
{
    static const char *const names[] = {"x-", "x+", "y-", "y+", "z-", "z+"};
    return (unsigned)f < 6 ? names[f] : "?";
}

static void body(sheet *s, const tf_problem *p)
{
    const tf_cloud *c = &p->cloud;
    const tf_mesh_geometry *g = tf_problem_mesh(p);
    if (g != NULL) {
        put(s, "  body: organ %s (crc32 0x%08x), %zu surface vertices; %zu nodes, interior spacing "
               "%g mm",
            g->file, (unsigned)g->file_crc32, c->n_surface, c->n, g->mesh.spacing);
        if (g->mesh.graded) {
            put(s, ", %g mm within %g mm of (%g, %g, %g)", g->mesh.grade_spacing,
                g->mesh.grade_radius, g->mesh.grade_at[0], g->mesh.grade_at[1],
                g->mesh.grade_at[2]);
        }
        if (g->mesh.refine_skin) {
            put(s, "; the skin refined to the spacing (%zu of its vertices the file's)",
                g->file_nv);
        }
        return;
    }
    const tf_box_geometry *b = &p->geometry.as.box;
    put(s, "  body: box [%g, %g] x [%g, %g] x [%g, %g] mm; %u x %u x %u nodes (%zu)", b->min[0],
        b->max[0], b->min[1], b->max[1], b->min[2], b->max[2], b->grid[0], b->grid[1], b->grid[2],
        c->n);
    if (c->graded) {
        put(s, ", graded (largest/smallest spacing %g, %g, %g)", b->grading.ratio[0],
            b->grading.ratio[1], b->grading.ratio[2]);
    }
    put(s, ", mean spacing %.3g x %.3g x %.3g mm", c->spacing[0], c->spacing[1], c->spacing[2]);
}

static void material(sheet *s, const tf_problem *p)
{
    const tf_law_ops *law = p->material.law;
    put(s, "\n  material: %s (%s):", law->name, law->summary);
    for (size_t i = 0; i < law->n_params; ++i) {
        put(s, "%s %s = %g (%s)", i ? "," : "", law->params[i].key, p->material.p[i],
            law->params[i].what);
    }
    for (size_t k = 0; k < p->n_inclusions; ++k) { /* material regions (inclusions.h) */
        const tf_inclusion *in = &p->inclusions[k];
        const tf_region *r = &in->where;
        put(s, "\n  inclusion %zu%s%s: ", k, in->name[0] ? " " : "", in->name);
        if (r->kind == TF_REGION_SPHERE && r->radius > 0) {
            put(s, "sphere centre (%g, %g, %g) mm, radius %g mm", r->centre[0], r->centre[1],
                r->centre[2], r->radius);
        } else if (r->kind == TF_REGION_SPHERE) {
            put(s, "ellipsoid centre (%g, %g, %g) mm, semi-axes %g, %g, %g mm along x, y, z",
                r->centre[0], r->centre[1], r->centre[2], in->radii[0], in->radii[1],
                in->radii[2]);
        } else {
            put(s, "box [%g, %g] x [%g, %g] x [%g, %g] mm", r->min[0], r->max[0], r->min[1],
                r->max[1], r->min[2], r->max[2]);
        }
        put(s, ", %s:", in->material.law->name);
        for (size_t i = 0; i < in->material.law->n_params; ++i) {
            put(s, "%s %s = %g", i ? "," : "", in->material.law->params[i].key, in->material.p[i]);
        }
        put(s, " (integrated point by point)");
    }
}

/* The solver and the settings its shape functions take: RPIM's support and
 * shape parameter, EFG's support, MLS collocation's neighbours. */
static void solver(sheet *s, const tf_problem *p)
{
    const tf_solver_opts *o = &p->solver;
    put(s, "\n  solver: %s", o->method);
    /* (the Galerkin solvers hand a law that is not linear elastic to
     * Newton's method: solvers/galerkin/galerkin.c) */
    int galerkin = strcmp(o->method, "rpim-galerkin") == 0 || strcmp(o->method, "efg-galerkin") == 0;
    if (galerkin && !tf_material_linear_elastic(&p->material)) {
        put(s, " (the %s law by Newton's method: %.4s-newton)", tf_material_name(&p->material),
            o->method);
    }
    if (strncmp(o->method, "mls-", 4) == 0) {
        put(s, ", %u neighbours, support %g mean neighbour distances", o->colloc.neighbours,
            o->colloc.support);
        return;
    }
    put(s, ", support %g spacings", o->support);
    if (strncmp(o->method, "rpim", 4) != 0) {
        return;
    }
    if (o->d_c_spacings > 0) {
        put(s, ", shape parameter d_c %g local spacings", o->d_c_spacings);
    } else {
        put(s, ", shape parameter d_c %g mm", o->d_c);
    }
}

static void region(sheet *s, const tf_region *r)
{
    switch (r->kind) {
    case TF_REGION_FACE:
        put(s, "face %s", face_name(r->face));
        break;
    case TF_REGION_PLANE:
        put(s, "plane %c = %g mm", "xyz"[r->axis % 3], r->at);
        break;
    case TF_REGION_BOX:
        put(s, "box [%g, %g] x [%g, %g] x [%g, %g] mm", r->min[0], r->max[0], r->min[1],
            r->max[1], r->min[2], r->max[2]);
        break;
    case TF_REGION_SPHERE:
        put(s, "ball of radius %g mm around (%g, %g, %g)", r->radius, r->centre[0], r->centre[1],
            r->centre[2]);
        break;
    case TF_REGION_SIDE:
        put(s, "side of the plane through (%g, %g, %g) normal (%g, %g, %g)", r->centre[0],
            r->centre[1], r->centre[2], r->normal[0], r->normal[1], r->normal[2]);
        break;
    case TF_REGION_NEAR:
        put(s, "surface within %g mm of (%g, %g, %g)", r->radius, r->centre[0], r->centre[1],
            r->centre[2]);
        break;
    case TF_REGION_VERTICES:
        put(s, "listed surface vertices");
        break;
    }
}

static void supports(sheet *s, const tf_problem *p)
{
    for (size_t i = 0; i < p->n_fixed; ++i) {
        const tf_fixed *f = &p->fixed[i];
        put(s, "\n  fixed %zu: ", i);
        region(s, &f->where);
        put(s, ", %zu nodes, %s", f->n_nodes,
            f->components == TF_COMP_ALL ? "every component held" : "some components held");
        if (f->value[0] != 0 || f->value[1] != 0 || f->value[2] != 0) {
            put(s, " at (%g, %g, %g) mm", f->value[0], f->value[1], f->value[2]);
        }
    }
}

static void site(sheet *s, const tf_problem *p, int contact)
{
    const tf_contact *c = &p->contacts[contact];
    const tf_patch *pa = &c->patch;
    put(s, "\n  contact '%s': (%g, %g, %g) mm", c->name, c->at[0], c->at[1], c->at[2]);
    switch (pa->shape) {
    case TF_PATCH_RECT:
        put(s, ", force spread over a %g x %g mm rectangle of face %s", pa->size[0], pa->size[1],
            face_name(pa->face));
        break;
    case TF_PATCH_CIRCLE:
        put(s, ", force spread over a disc of radius %g mm on face %s", pa->radius,
            face_name(pa->face));
        break;
    case TF_PATCH_SURFACE:
    case TF_PATCH_POINTS:
        put(s, ", force spread over %.4g mm^2 of the surface", pa->area);
        break;
    case TF_PATCH_FACE:
        put(s, ", force spread over face %s", face_name(pa->face));
        break;
    case TF_PATCH_POINT:
    case TF_PATCH_AT:
        put(s, ", a point force");
        break;
    }
    put(s, "; envelope |F - (%g, %g, %g)| <= %g N", p->envelope.centre[0], p->envelope.centre[1],
        p->envelope.centre[2], p->envelope.radius);
}

size_t tf_problem_datasheet(const tf_problem *p, int contact, char *buf, size_t n)
{
    sheet s = {buf, n, 0};
    if (n == 0) {
        return 0;
    }
    buf[0] = '\0';
    body(&s, p);
    material(&s, p);
    solver(&s, p);
    supports(&s, p);
    if (contact >= 0 && (size_t)contact < p->n_contacts) {
        site(&s, p, contact);
    }
    return s.len;
}
