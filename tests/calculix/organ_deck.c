/*
 * organ_deck.c — writes a CalculiX input deck (.inp) for an organ scene
 * (geometry.surface) on stdout: the same volume, fixed region and contact
 * patch as the meshless solve, meshed by gmsh with 10-node tetrahedra
 * (C3D10), one *STEP per unit force (1 N along x, y and z).
 *
 *   organ_deck SCENE --spacing H [--grade G] [--refine R] [--solver NAME]
 *              [--inclusion-spacing HI] [--quantum Q] [--nlgeom FX,FY,FZ [--levels K]]
 *              [--sites A,B[:A,B...] [--patch-refine E]]
 *
 * Mesh (geometry/volume_mesh_tet10.h): the scene's surface as it is (every
 * vertex a node), the interior at spacing H mm (--grade G: G mm within
 * 20 mm of the contact vertex, rising linearly to H at 60 mm), then R
 * uniform refinements (each tetrahedron into eight; the surface triangles
 * into four on their own planes: the same polyhedron), then second order.
 *
 * A box scene (geometry.box, its material regions meshed to conform, which
 * box_deck.c's hexahedra cannot) is meshed the same way from its surface
 * split into squares of Q mm (--quantum; each side a multiple of it, and
 * the patch's edges and the output nodes on its lines), each square into
 * two triangles; its contact patch is a rectangle of a face, its fixed
 * regions may be faces, its outputs are the scene's output nodes ("** OUT"
 * and "** CONTACT" then carry the meshless node index), and --grade grades
 * towards the patch's centre.
 *
 * Material regions (the scene's inclusions, spheres and ellipsoids): each
 * is its own volume of the mesh, bounded by a triangulated ellipsoid
 * (geometry/ellipsoid_surface.h, edges at most HI mm, default the smaller
 * of H and a quarter of its largest semi-axis) that the tetrahedra conform
 * to, meshed at HI mm inside and up to one semi-axis beyond, rising to H
 * one semi-axis further; its elements get the inclusion's material.  The
 * faceted boundary lies inside the true one: its volume is stated on a
 * "** INCLUSION" line beside the ellipsoid's.  Inclusions that overlap (by
 * their bounding balls) or are boxes are refused.
 *
 * Fixed region: every node (corner or mid-edge) the scene's fixed regions
 * select by position (box, sphere, side; not the vertex-based near and
 * vertices, which name the meshless cloud's nodes).  All three components.
 *
 * Load: CalculiX's *DLOAD has no tangential surface traction, so each unit
 * force is applied as the consistent nodal loads of the uniform traction
 * t = F / A over the boundary faces inside the scene's contact patch (A its
 * area): on a flat 6-node triangle the corners get 0 and each mid-edge node
 * A_face t / 3 (the integrals of the quadratic shape functions).  A face
 * belongs to the patch when its centroid lies in one of the patch's
 * triangles (refined faces subdivide them); the deck writer checks that
 * the faces' area equals the patch's to 1e-9.
 *
 * A contact region (an organ's, --sites: at most 8 points (a, b) of its
 * chart's domain, problem/region_chart.h): at each site the probe's patch
 * as the meshless region fit loads it (the surface that projects into the
 * tip's disc, as quadrature points on the file's triangles), each point's
 * weight given to the 6-node boundary face that holds it as w N_i (the
 * consistent loads of the uniform traction over exactly that patch), and
 * three unit-force steps per site ("s<k>fx" .. "s<k>fz"); set OUT is the
 * patches' nodes, so that the patch-averaged displacement, the
 * work-conjugate of the probe's force, is sum_i w_i u_i (region_dat.awk).
 * The traction jumps at the patch's edge, inside the file's triangles:
 * --patch-refine E splits the skin's triangles on their own planes
 * (surface_refine.h) until their edges are about E mm at the edge of every
 * site's patch, growing by the distance from it, before the volume is
 * meshed (docs/validation.md §14.2 measures what it changes).  With one
 * site, --grade G grades the interior towards its surface point (G mm
 * within 20 mm, rising to H at 60 mm); with more, --grade is refused.
 *
 * Large deformation (--nlgeom, a neo-Hookean scene): one step instead,
 * NLGEOM, the force F ramped from zero and the outputs printed at K equal
 * load levels (*TIME POINTS; default 4), CalculiX's automatic increments at
 * most a level each and Newton held to 1e-6 (*CONTROLS, as box_deck.c's
 * NLGEOM reference); each material *HYPERELASTIC, NEO HOOKE with C10 = mu/2
 * and D1 = 2/K (the energy host/materials/neohooke.c writes down).  The
 * load is dead (*CLOAD keeps its direction).  Each printed level is
 * described by a "** STEP k lk fx fy fz" line (its force), so that the
 * extraction reads it as a case.
 *
 * Comment lines the extraction reads (CalculiX ignores lines starting **):
 *   ** SIZE elements nodes dofs
 *   ** STEP n case fx fy fz
 *   ** OUT vertex ccx_node x y z     (the scene's outputs, then the contact
 *                                    vertex if it is not one of them)
 *   ** CONTACT vertex ccx_node
 *   ** SITE k a b x y z area          (--sites: site k, its surface point)
 *   ** PATCH k ccx_node weight        (--sites: its loads per unit force)
 *   ** PATCH-REFINE E: n skin vertices (the file's m)   (--patch-refine)
 *
 * Exit 0 ok, 1 meshing failed, 2 bad usage or scene (nothing written).
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/ellipsoid_surface.h"
#include "geometry/surface_refine.h"
#include "geometry/volume_mesh_tet10.h"
#include "problem/mesh_geometry.h"
#include "problem/region_chart.h"
#include "problem/regions.h"
#include "scene/scene.h"

/* C3D10 faces: corners and the mid-edge nodes between them (deck order). */
static const int face[4][6] = {
    {0, 1, 2, 4, 5, 6}, {0, 3, 1, 7, 8, 4}, {1, 3, 2, 8, 9, 5}, {2, 3, 0, 9, 7, 6}};

/* Most sites of a region deck (--sites). */
#define SITES_MAX 8

typedef struct options {
    const char *scene, *solver;
    double spacing, inclusion_spacing, quantum;
    int nlgeom, levels;  /* --nlgeom: one ramped step to force, printed at levels */
    double force[3];
    unsigned refine;
    double grade; /* mm near the contact vertex, 0: none */
    double sites[2 * SITES_MAX]; /* --sites: a region's sites (a, b), chart frame, mm */
    int n_sites;
    double patch_refine; /* --patch-refine: the skin's edges at the patches' edges, mm (0: none) */
} options;

static int usage(void)
{
    fprintf(stderr, "usage: organ_deck SCENE --spacing H [--grade G] [--refine R] [--solver NAME]\n"
                    "                  [--inclusion-spacing HI] [--quantum Q]\n"
                    "                  [--nlgeom FX,FY,FZ [--levels K]]\n"
                    "                  [--sites A,B[:A,B...] [--patch-refine E]]\n");
    return 2;
}

/* --sites A,B[:A,B...]: at most SITES_MAX points of the region's domain. */
static int parse_sites(const char *arg, options *o)
{
    const char *p = arg;
    char *end;
    for (o->n_sites = 0; *p; ++o->n_sites) {
        if (o->n_sites == SITES_MAX) {
            return -1;
        }
        double *ab = o->sites + 2 * o->n_sites;
        ab[0] = strtod(p, &end);
        if (end == p || *end != ',') {
            return -1;
        }
        p = end + 1;
        ab[1] = strtod(p, &end);
        if (end == p || (*end != ':' && *end != 0) || (*end == ':' && end[1] == 0) ||
            !isfinite(ab[0]) || !isfinite(ab[1])) {
            return -1;
        }
        p = *end ? end + 1 : end;
    }
    return o->n_sites > 0 ? 0 : -1;
}

static int parse(int argc, char **argv, options *o)
{
    static const struct option opts[] = {{"spacing", required_argument, NULL, 's'},
                                         {"refine", required_argument, NULL, 'r'},
                                         {"solver", required_argument, NULL, 'v'},
                                         {"grade", required_argument, NULL, 'g'},
                                         {"inclusion-spacing", required_argument, NULL, 'i'},
                                         {"quantum", required_argument, NULL, 'q'},
                                         {"nlgeom", required_argument, NULL, 'n'},
                                         {"levels", required_argument, NULL, 'l'},
                                         {"sites", required_argument, NULL, 'a'},
                                         {"patch-refine", required_argument, NULL, 'p'},
                                         {0}};
    int c;
    char *end;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (c == 's') {
            o->spacing = strtod(optarg, &end);
            if (*end || !(o->spacing > 0)) {
                return -1;
            }
        } else if (c == 'r') {
            o->refine = (unsigned)strtoul(optarg, &end, 10);
            if (*end || o->refine > 3) {
                return -1;
            }
        } else if (c == 'v') {
            o->solver = optarg;
        } else if (c == 'q') {
            o->quantum = strtod(optarg, &end);
            if (*end || !(o->quantum > 0)) {
                return -1;
            }
        } else if (c == 'i') {
            o->inclusion_spacing = strtod(optarg, &end);
            if (*end || !(o->inclusion_spacing > 0)) {
                return -1;
            }
        } else if (c == 'g') {
            o->grade = strtod(optarg, &end);
            if (*end || !(o->grade > 0)) {
                return -1;
            }
        } else if (c == 'n') {
            o->nlgeom = sscanf(optarg, "%lf,%lf,%lf", &o->force[0], &o->force[1], &o->force[2]) == 3;
            if (!o->nlgeom) {
                return -1;
            }
        } else if (c == 'p') {
            o->patch_refine = strtod(optarg, &end);
            if (*end || !(o->patch_refine > 0)) {
                return -1;
            }
        } else if (c == 'a') {
            if (parse_sites(optarg, o) != 0) {
                return -1;
            }
        } else if (c == 'l') {
            o->levels = (int)strtol(optarg, &end, 10);
            if (*end || o->levels < 1 || o->levels > 100) {
                return -1;
            }
        } else {
            return -1;
        }
    }
    if (optind + 1 != argc || !(o->spacing > 0) || (o->levels && !o->nlgeom) ||
        (o->n_sites && o->nlgeom) || (o->patch_refine > 0 && !o->n_sites) ||
        (o->grade > 0 && o->n_sites > 1)) {
        return -1;
    }
    o->levels = o->nlgeom && o->levels == 0 ? 4 : o->levels;
    o->scene = argv[optind];
    return 0;
}

/* --patch-refine: the skin's edge length wanted at x: E at the edge of a
 * site's patch (the circle of the tip's radius about the site, in the
 * chart plane), growing by the distance from it. */
typedef struct patch_field {
    const options *o;
    const tf_contact_region *r;
} patch_field;

static double patch_size(const double x[3], const void *arg)
{
    const patch_field *f = arg;
    double q[3], d = INFINITY;
    tf_region_chart_coords(&f->r->chart, x, q);
    for (int k = 0; k < f->o->n_sites; ++k) {
        double rho = hypot(q[0] - f->o->sites[2 * k], q[1] - f->o->sites[2 * k + 1]);
        d = fmin(d, fabs(rho - f->r->tip_radius));
    }
    return f->o->patch_refine + d;
}

/* The organ's surface as the meshless solve placed it: the file's vertices
 * and triangles (a refined skin, geometry.refine_skin, is the meshless
 * solve's own resolution, not the reference's: the deck refines by
 * --refine). */
static int surface_of(const tf_mesh_geometry *m, tf_surface *s)
{
    if (tf_surface_alloc(s, m->file_nv, m->file_nt) != 0) {
        return -1;
    }
    memcpy(s->xyz, m->tm.xyz, 3 * m->file_nv * sizeof *s->xyz);
    memcpy(s->tri, m->file_tri, 3 * m->file_nt * sizeof *s->tri);
    for (size_t i = 0; i < m->file_nv; ++i) {
        s->source[i] = m->tm.source[i];
    }
    return 0;
}

/* A box scene's surface: its faces split into squares of side q, each
 * into two triangles wound counter-clockwise seen from outside; -1 when a
 * side is not a multiple of q (or out of memory). */
static int box_surface(const tf_problem *p, double q, tf_surface *s)
{
    const double *lo = p->cloud.lo, *hi = p->cloud.hi;
    size_t n[3], id_count = 1;
    for (int a = 0; a < 3; ++a) {
        double k = round((hi[a] - lo[a]) / q);
        if (!(k >= 1 && fabs(k * q - (hi[a] - lo[a])) <= 1e-9 * (hi[a] - lo[a]))) {
            fprintf(stderr, "organ_deck: the box's side %g mm along %c is not a multiple of "
                            "--quantum %g\n", hi[a] - lo[a], 'x' + a, q);
            return -1;
        }
        n[a] = (size_t)k;
        id_count *= n[a] + 1;
    }
    size_t nv = id_count - (n[0] - 1) * (n[1] - 1) * (n[2] - 1);
    size_t nt = 4 * (n[0] * n[1] + n[1] * n[2] + n[0] * n[2]);
    size_t *id = malloc(id_count * sizeof *id);
    if (id == NULL || tf_surface_alloc(s, nv, nt) != 0) {
        free(id);
        fprintf(stderr, "organ_deck: out of memory\n");
        return -1;
    }
    size_t v = 0, t = 0;
    for (size_t k = 0; k <= n[2]; ++k) { /* lattice points on the boundary */
        for (size_t j = 0; j <= n[1]; ++j) {
            for (size_t i = 0; i <= n[0]; ++i) {
                size_t l = i + (n[0] + 1) * (j + (n[1] + 1) * k), ijk[3] = {i, j, k};
                int boundary = 0;
                for (int a = 0; a < 3; ++a) {
                    boundary |= ijk[a] == 0 || ijk[a] == n[a];
                }
                id[l] = boundary ? v : SIZE_MAX;
                for (int a = 0; boundary && a < 3; ++a) {
                    s->xyz[3 * v + (size_t)a] =
                        ijk[a] == n[a] ? hi[a] : lo[a] + (double)ijk[a] * q;
                }
                v += (size_t)boundary;
            }
        }
    }
    for (int a = 0; a < 3; ++a) { /* face a-min (side 0) and a-max (side 1) */
        int u = (a + 1) % 3, w = (a + 2) % 3; /* (u, w, a) right-handed */
        for (int side = 0; side < 2; ++side) {
            for (size_t i = 0; i < n[u]; ++i) {
                for (size_t j = 0; j < n[w]; ++j) {
                    size_t c[4];
                    for (int corner = 0; corner < 4; ++corner) {
                        size_t ijk[3];
                        ijk[a] = side ? n[a] : 0;
                        ijk[u] = i + (corner == 1 || corner == 2);
                        ijk[w] = j + (corner >= 2);
                        c[corner] = id[ijk[0] + (n[0] + 1) * (ijk[1] + (n[1] + 1) * ijk[2])];
                    }
                    /* c0 c1 c2 c3 counter-clockwise seen from +a */
                    size_t tri[2][3] = {{c[0], c[1], c[2]}, {c[0], c[2], c[3]}};
                    for (int h = 0; h < 2; ++h, ++t) {
                        s->tri[3 * t] = tri[h][0];
                        s->tri[3 * t + 1] = side ? tri[h][1] : tri[h][2];
                        s->tri[3 * t + 2] = side ? tri[h][2] : tri[h][1];
                    }
                }
            }
        }
    }
    free(id);
    return 0;
}

/* Is g in the box scene's rectangular patch (on its face's plane)? */
static int in_rect(const double *g, const tf_problem *p, const tf_patch *pt)
{
    tf_cloud c = p->cloud;
    int u, v, a = tf_face_axis(pt->face);
    tf_face_axes(pt->face, &u, &v);
    double tol = 1e-9 * (p->cloud.hi[a] - p->cloud.lo[a] + 1);
    return fabs(g[a] - tf_cloud_face_coord(&c, pt->face)) <= tol &&
           fabs(g[u] - pt->centre[0]) <= 0.5 * pt->size[0] &&
           fabs(g[v] - pt->centre[1]) <= 0.5 * pt->size[1];
}

static double tri_area(const double *a, const double *b, const double *c, double n[3])
{
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    return 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* Is g inside triangle abc (in its plane, within a relative tolerance)? */
static int in_triangle(const double *g, const double *a, const double *b, const double *c)
{
    double n[3], sub[3];
    double area = tri_area(a, b, c, n), scale = sqrt(area);
    double d = ((g[0] - a[0]) * n[0] + (g[1] - a[1]) * n[1] + (g[2] - a[2]) * n[2]) / (2 * area);
    if (fabs(d) > 1e-9 * scale) {
        return 0;
    }
    const double *p[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) { /* the sub-triangle opposite corner k has the same sense */
        tri_area(g, p[(k + 1) % 3], p[(k + 2) % 3], sub);
        if (sub[0] * n[0] + sub[1] * n[1] + sub[2] * n[2] < -1e-12 * area * area) {
            return 0;
        }
    }
    return 1;
}

/* Is the boundary face centroid g in the patch: a box's rectangle, or one
 * of an organ's patch triangles? */
static int in_patch(const double *g, const tf_problem *p, const tf_patch *pt)
{
    if (pt->shape == TF_PATCH_RECT) {
        return in_rect(g, p, pt);
    }
    const double *x = p->cloud.xyz;
    for (size_t j = 0; j < pt->n_tri; ++j) {
        const uint32_t *v = pt->tri + 3 * j;
        if (in_triangle(g, x + 3 * (size_t)v[0], x + 3 * (size_t)v[1], x + 3 * (size_t)v[2])) {
            return 1;
        }
    }
    return 0;
}

typedef struct face_key {
    size_t c[3]; /* sorted corners */
    size_t tet;
    int f;
} face_key;

static int cmp_face(const void *x, const void *y)
{
    const face_key *a = x, *b = y;
    for (int k = 0; k < 3; ++k) {
        if (a->c[k] != b->c[k]) {
            return a->c[k] < b->c[k] ? -1 : 1;
        }
    }
    return 0;
}

static void sort3(size_t *c)
{
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2 - i; ++j) {
            if (c[j] > c[j + 1]) {
                size_t t = c[j];
                c[j] = c[j + 1];
                c[j + 1] = t;
            }
        }
    }
}

/* A boundary face of the mesh: face f of tetrahedron tet (no other
 * tetrahedron has it). */
typedef struct bface {
    size_t tet;
    int f;
} bface;

/* The boundary faces of q (*n of them; NULL when out of memory). */
static bface *boundary_faces(const tf_tet10_mesh *q, size_t *n)
{
    face_key *k = malloc((4 * q->ntet + 1) * sizeof *k);
    bface *b = malloc((4 * q->ntet + 1) * sizeof *b);
    if (k == NULL || b == NULL) {
        free(k);
        free(b);
        return NULL;
    }
    for (size_t e = 0; e < q->ntet; ++e) {
        for (int f = 0; f < 4; ++f) {
            face_key *fk = &k[4 * e + (size_t)f];
            for (int j = 0; j < 3; ++j) {
                fk->c[j] = q->tet[10 * e + (size_t)face[f][j]];
            }
            sort3(fk->c);
            fk->tet = e;
            fk->f = f;
        }
    }
    qsort(k, 4 * q->ntet, sizeof *k, cmp_face);
    *n = 0;
    for (size_t i = 0; i < 4 * q->ntet; ++i) {
        int shared = (i > 0 && cmp_face(&k[i], &k[i - 1]) == 0) ||
                     (i + 1 < 4 * q->ntet && cmp_face(&k[i], &k[i + 1]) == 0);
        if (!shared) {
            b[(*n)++] = (bface){k[i].tet, k[i].f};
        }
    }
    free(k);
    return b;
}

/* The corners of boundary face b. */
static void face_corners(const tf_tet10_mesh *q, bface b, const double *c[3])
{
    const size_t *t = q->tet + 10 * b.tet;
    for (int j = 0; j < 3; ++j) {
        c[j] = q->xyz + 3 * t[face[b.f][j]];
    }
}

/* Nodal loads per unit traction (load[3 node] += A/3 at each mid-edge node
 * of every boundary face in the patch); returns the loaded area, or -1. */
static double patch_loads(const tf_tet10_mesh *q, const tf_problem *p, const tf_patch *pt,
                          double *weight)
{
    size_t nb;
    bface *b = boundary_faces(q, &nb);
    if (b == NULL) {
        return -1;
    }
    double area = 0;
    for (size_t i = 0; i < nb; ++i) {
        const double *c[3];
        face_corners(q, b[i], c);
        double g[3] = {(c[0][0] + c[1][0] + c[2][0]) / 3, (c[0][1] + c[1][1] + c[2][1]) / 3,
                       (c[0][2] + c[1][2] + c[2][2]) / 3};
        if (in_patch(g, p, pt)) {
            double n[3], fa = tri_area(c[0], c[1], c[2], n);
            const size_t *t = q->tet + 10 * b[i].tet;
            area += fa;
            for (int m = 3; m < 6; ++m) {
                weight[t[face[b[i].f][m]]] += fa / 3;
            }
        }
    }
    free(b);
    return area;
}

/* How far x is from flat face abc: the larger of its distance from the
 * face's plane (relative to the face's size) and how far outside the face
 * its barycentric coordinates L (written) are. */
static double face_miss(const double *x, const double *a, const double *b, const double *c,
                        double L[3])
{
    double n[3], sub[3];
    double area2 = 2 * tri_area(a, b, c, n), nn = area2 * area2;
    const double *p[3] = {a, b, c};
    double miss = fabs((x[0] - a[0]) * n[0] + (x[1] - a[1]) * n[1] + (x[2] - a[2]) * n[2]) /
                  (area2 * sqrt(0.5 * area2));
    for (int k = 0; k < 3; ++k) { /* the sub-triangle opposite corner k, signed */
        tri_area(x, p[(k + 1) % 3], p[(k + 2) % 3], sub);
        L[k] = (sub[0] * n[0] + sub[1] * n[1] + sub[2] * n[2]) / nn;
        miss = fmax(miss, -L[k]);
    }
    return miss;
}

/* The consistent nodal loads of a uniform unit traction over a patch given
 * by quadrature points (a region's probe patch at one site, TF_PATCH_POINTS:
 * on an organ its points lie on the file's triangles, which the mesh's
 * boundary faces subdivide on their own planes): each point's weight w,
 * over the 6-node face that holds it, as w N_i (corners L (2 L - 1),
 * mid-edge nodes 4 L_i L_j).  weight (nn) is added to; returns the weights'
 * total (the patch's area), or -1 with a message when a point lies on no
 * boundary face (to 1e-9 of a face's size). */
static double point_loads(const tf_tet10_mesh *q, const bface *b, size_t nb, const tf_patch *pt,
                          double *weight)
{
    double area = 0;
    for (size_t i = 0; i < pt->n_pts; ++i) {
        const double *x = pt->pts + 4 * i, w = pt->pts[4 * i + 3];
        double best = INFINITY, L[3], Lb[3] = {0};
        size_t at = 0;
        for (size_t j = 0; j < nb && best > 0; ++j) {
            const double *c[3];
            face_corners(q, b[j], c);
            int near = 1;
            for (int a = 0; a < 3 && near; ++a) {
                double lo = fmin(c[0][a], fmin(c[1][a], c[2][a])), hi = fmax(c[0][a], fmax(c[1][a], c[2][a]));
                near = x[a] >= lo - 1e-6 && x[a] <= hi + 1e-6;
            }
            double miss = near ? face_miss(x, c[0], c[1], c[2], L) : INFINITY;
            if (miss < best) {
                best = miss;
                at = j;
                memcpy(Lb, L, sizeof Lb);
            }
        }
        if (!(best <= 1e-9)) {
            fprintf(stderr, "organ_deck: the patch's point (%g, %g, %g) lies on no boundary face "
                            "(nearest %.3g of a face's size away)\n", x[0], x[1], x[2], best);
            return -1;
        }
        const size_t *t = q->tet + 10 * b[at].tet;
        const int *fc = face[b[at].f];
        for (int k = 0; k < 3; ++k) {
            weight[t[fc[k]]] += w * Lb[k] * (2 * Lb[k] - 1);
            weight[t[fc[3 + k]]] += w * 4 * Lb[k] * Lb[(k + 1) % 3];
        }
        area += w;
    }
    return area;
}

/* Nodes of the fixed regions (by position). */
static int fixed_nodes(const tf_tet10_mesh *q, const tf_problem *p, unsigned char *fixed)
{
    tf_cloud c = {.n = q->nn, .xyz = q->xyz};
    for (int a = 0; a < 3; ++a) {
        c.lo[a] = p->cloud.lo[a];
        c.hi[a] = p->cloud.hi[a];
    }
    const int organ = tf_problem_mesh(p) != NULL;
    for (size_t r = 0; r < p->n_fixed; ++r) {
        tf_region_kind kind = p->fixed[r].where.kind;
        if (kind == TF_REGION_NEAR || kind == TF_REGION_VERTICES || (organ && kind == TF_REGION_FACE)) {
            fprintf(stderr, "organ_deck: fixed.%zu: only box, plane, sphere and side regions "
                            "carry over to another mesh\n", r);
            return -1;
        }
        uint32_t *nodes;
        size_t n;
        if (tf_region_nodes(&c, &p->fixed[r].where, &nodes, &n) != 0) {
            return -1;
        }
        for (size_t i = 0; i < n; ++i) {
            fixed[nodes[i]] = 1;
        }
        free(nodes);
    }
    return 0;
}

/* A coordinate as CalculiX reads it: a field holds at most 20 characters,
 * so %.17g (exact) when it fits, else %.14g (1e-14 relative). */
static const char *coordinate(double v, char *buf, size_t len)
{
    if (snprintf(buf, len, "%.17g", v) > 20) {
        snprintf(buf, len, "%.14g", v);
    }
    return buf;
}

static void write_mesh(const tf_tet10_mesh *q)
{
    char a[32], b[32], c[32];
    printf("*NODE, NSET=NALL\n");
    for (size_t i = 0; i < q->nn; ++i) {
        printf("%zu, %s, %s, %s\n", i + 1, coordinate(q->xyz[3 * i], a, sizeof a),
               coordinate(q->xyz[3 * i + 1], b, sizeof b), coordinate(q->xyz[3 * i + 2], c, sizeof c));
    }
    for (size_t e = 0; e < q->ntet; ++e) {
        if (e == 0 || q->region[e] != q->region[e - 1]) {
            if (q->region[e] == 0) {
                printf("*ELEMENT, TYPE=C3D10, ELSET=ORGAN\n");
            } else {
                printf("*ELEMENT, TYPE=C3D10, ELSET=INC%d\n", q->region[e]);
            }
        }
        printf("%zu", e + 1);
        for (int k = 0; k < 10; ++k) {
            printf(", %zu", q->tet[10 * e + (size_t)k] + 1);
        }
        printf("\n");
    }
}

static void write_set(const char *name, const unsigned char *in, size_t n)
{
    size_t count = 0;
    printf("*NSET, NSET=%s\n", name);
    for (size_t i = 0; i < n; ++i) {
        if (in[i]) {
            printf("%zu,%s", i + 1, ++count % 8 == 0 ? "\n" : " ");
        }
    }
    printf("\n");
}

/* The scene's outputs and the contact vertex, as "** OUT" lines and set OUT. */
/* The mesh node at x (a box scene's output node), or SIZE_MAX. */
static size_t node_at(const tf_tet10_mesh *q, const double *x)
{
    size_t best = SIZE_MAX;
    double d = 1e-18 * (1 + x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    for (size_t i = 0; i < q->nn; ++i) {
        const double *y = q->xyz + 3 * i;
        double e = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                   (x[2] - y[2]) * (x[2] - y[2]);
        if (e <= d) {
            d = e;
            best = i;
        }
    }
    return best;
}

/* The scene's outputs and the contact vertex (an organ's vertex index in
 * its file, a box's meshless node index), as "** OUT" lines and set OUT. */
static int write_outputs(const tf_tet10_mesh *q, const tf_problem *p, unsigned char *out)
{
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    uint32_t contact = p->contacts[0].node;
    int contact_listed = 0;
    size_t contact_node = SIZE_MAX;
    for (size_t j = 0; j <= p->outputs.n_nodes; ++j) {
        uint32_t v = j < p->outputs.n_nodes ? p->outputs.nodes[j] : contact;
        if (j == p->outputs.n_nodes && contact_listed) {
            break;
        }
        contact_listed |= v == contact;
        size_t node = m ? q->vertex_node[v] : node_at(q, p->cloud.xyz + 3 * (size_t)v);
        if (node == SIZE_MAX) {
            fprintf(stderr, "organ_deck: output node %u is on no line of the quantum\n", v);
            return -1;
        }
        contact_node = v == contact ? node : contact_node;
        out[node] = 1;
        printf("** OUT %ld %zu %.17g %.17g %.17g\n", m ? m->tm.source[v] : (long)v, node + 1,
               q->xyz[3 * node], q->xyz[3 * node + 1], q->xyz[3 * node + 2]);
    }
    printf("** CONTACT %ld %zu\n", m ? m->tm.source[contact] : (long)contact, contact_node + 1);
    return 0;
}

/* --nlgeom: one step, the force ramped to o->force, printed at o->levels
 * equal levels (each described as a case), Newton to 1e-6. */
static void write_nlgeom_step(const options *o, const double *weight, size_t nn, double area)
{
    const double dt = 1.0 / o->levels;
    for (int k = 1; k <= o->levels; ++k) {
        const double f = (double)k / o->levels;
        printf("** STEP %d l%d %.17g %.17g %.17g\n", k, k, f * o->force[0], f * o->force[1],
               f * o->force[2]);
    }
    printf("*TIME POINTS, NAME=RAMP\n");
    for (int k = 1; k <= o->levels; ++k) {
        printf("%.15g\n", (double)k / o->levels);
    }
    printf("*STEP, NLGEOM, INC=%d\n*STATIC%s%s\n%.15g,1.,%.15g,%.15g\n", 100 * o->levels,
           o->solver ? ", SOLVER=" : "", o->solver ? o->solver : "", dt, dt * 1e-2, dt);
    printf("*CONTROLS, PARAMETERS=FIELD\n1e-6,1e-6,,,1e-6\n*CLOAD, OP=NEW\n");
    for (size_t i = 0; i < nn; ++i) {
        for (int a = 0; a < 3; ++a) {
            if (weight[i] != 0 && o->force[a] != 0) {
                printf("%zu, %d, %.12e\n", i + 1, a + 1, weight[i] / area * o->force[a]);
            }
        }
    }
    printf("*NODE PRINT, NSET=OUT, TIME POINTS=RAMP\nU\n*NODE PRINT, NSET=FIXED, TOTALS=ONLY, "
           "TIME POINTS=RAMP\nRF\n*END STEP\n");
}

/* The material card of m: *ELASTIC, or with --nlgeom the neo-Hookean energy
 * of the same small-strain moduli (C10 = mu / 2, D1 = 2 / K). */
static void write_material(const options *o, const char *name, const tf_material *m)
{
    double young, poisson;
    tf_material_moduli(m, &young, &poisson);
    printf("*MATERIAL, NAME=%s\n", name);
    if (!o->nlgeom) {
        printf("*ELASTIC\n%.17g, %.17g\n", young, poisson);
        return;
    }
    double mu = young / (2 * (1 + poisson)), bulk = young / (3 * (1 - 2 * poisson));
    printf("** neo-Hooke: mu = %.15g MPa, K = %.15g MPa\n*HYPERELASTIC, NEO HOOKE\n%.15g, %.15g\n",
           mu, bulk, mu / 2, 2 / bulk);
}

static void write_steps(const tf_problem *p, const double *weight, size_t nn, double area,
                        const char *solver)
{
    static const char *const name[3] = {"fx", "fy", "fz"};
    for (int s = 0; s < 3; ++s) {
        printf("** STEP %d %s %d %d %d\n** load case %s: 1 N as a uniform traction over %.10g "
               "mm^2\n*STEP\n*STATIC%s%s\n*CLOAD, OP=NEW\n",
               s + 1, name[s], s == 0, s == 1, s == 2, name[s], area, solver ? ", SOLVER=" : "",
               solver ? solver : "");
        for (size_t i = 0; i < nn; ++i) {
            if (weight[i] != 0) {
                printf("%zu, %d, %.17g\n", i + 1, s + 1, weight[i] / area);
            }
        }
        printf("*NODE PRINT, NSET=OUT\nU\n*NODE PRINT, NSET=FIXED, TOTALS=ONLY\nRF\n*END STEP\n");
    }
    (void)p;
}

/* Each inclusion's boundary as an inner surface of the mesh (ellipsoids
 * only, not overlapping); "** INCLUSION k volume faceted exact" lines. */
static int inclusion_surfaces(const options *o, const tf_problem *p, tf_surface *skin,
                              tf_mesh_inner *inner)
{
    for (size_t k = 0; k < p->n_inclusions; ++k) {
        const tf_inclusion *c = &p->inclusions[k];
        const double *r = c->radii;
        double rmax = fmax(r[0], fmax(r[1], r[2]));
        double h = o->inclusion_spacing > 0 ? o->inclusion_spacing : fmin(o->spacing, rmax / 4);
        int bad = c->where.kind != TF_REGION_SPHERE;
        for (size_t j = 0; j < k && !bad; ++j) {
            const tf_inclusion *d = &p->inclusions[j];
            double dr = fmax(d->radii[0], fmax(d->radii[1], d->radii[2])), dd = 0;
            for (int a = 0; a < 3; ++a) {
                dd += (c->where.centre[a] - d->where.centre[a]) * (c->where.centre[a] - d->where.centre[a]);
            }
            bad = sqrt(dd) <= rmax + dr;
        }
        if (bad || tf_surface_ellipsoid(&skin[k], c->where.centre, r, h) != 0) {
            fprintf(stderr, "organ_deck: inclusions.%zu: %s\n", k,
                    bad ? "only spheres and ellipsoids whose bounding balls do not overlap are meshed"
                        : "its surface could not be made");
            for (size_t j = 0; j < k; ++j) {
                tf_surface_free(&skin[j]);
            }
            return -1;
        }
        inner[k] = (tf_mesh_inner){.surface = &skin[k], .radius = rmax, .spacing = h};
        memcpy(inner[k].centre, c->where.centre, sizeof inner[k].centre);
        printf("** INCLUSION %zu %.10g %.10g\n", k + 1, tf_surface_volume(&skin[k]),
               4.0 / 3 * M_PI * r[0] * r[1] * r[2]);
    }
    return 0;
}

/* --sites: the unit-traction nodal loads of the region's probe patch at
 * each site (w: n_sites x nn, per unit force: each row sums to 1), "** SITE
 * k a b x y z" and "** PATCH k node weight" lines, and the patches' nodes
 * in out (set OUT).  Returns 0, or 1 with a message. */
static int site_loads(const options *o, const tf_problem *p, const tf_tet10_mesh *q, double *w,
                      unsigned char *out)
{
    const tf_contact_region *r = &p->contacts[0].region;
    size_t nb;
    bface *b = boundary_faces(q, &nb);
    if (b == NULL) {
        fprintf(stderr, "organ_deck: out of memory\n");
        return 1;
    }
    int rc = 0;
    for (int k = 0; k < o->n_sites && rc == 0; ++k) {
        const double a = o->sites[2 * k], bb = o->sites[2 * k + 1];
        tf_patch patch = {0};
        double x[3], *wk = w + (size_t)k * q->nn;
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        if (tf_region_site_patch(&ctx, p, r, a, bb, &patch, x) != 0) {
            fprintf(stderr, "organ_deck: --sites: (%g, %g): %s\n", a, bb, ctx.err);
            rc = 2;
        } else {
            double area = point_loads(q, b, nb, &patch, wk);
            rc = area > 0 ? 0 : 1;
            printf("** SITE %d %.17g %.17g %.17g %.17g %.17g %.10g\n", k + 1, a, bb, x[0], x[1],
                   x[2], area);
            for (size_t i = 0; i < q->nn && rc == 0; ++i) {
                if (wk[i] != 0) {
                    wk[i] /= area;
                    out[i] = 1;
                    char v[32]; /* as the steps write it: CalculiX's fields hold 20 characters */
                    printf("** PATCH %d %zu %s\n", k + 1, i + 1, coordinate(wk[i], v, sizeof v));
                }
            }
        }
        tf_patch_release(&patch);
    }
    free(b);
    return rc;
}

/* --sites: three unit-force steps per site, "s<k>fx" .. "s<k>fz". */
static void write_site_steps(const options *o, const double *w, size_t nn, const char *solver)
{
    static const char *const name[3] = {"fx", "fy", "fz"};
    for (int k = 0; k < o->n_sites; ++k) {
        for (int s = 0; s < 3; ++s) {
            printf("** STEP %d s%d%s %d %d %d\n** site %d, load case %s: 1 N as a uniform "
                   "traction over the probe's patch\n*STEP\n*STATIC%s%s\n*CLOAD, OP=NEW\n",
                   3 * k + s + 1, k + 1, name[s], s == 0, s == 1, s == 2, k + 1, name[s],
                   solver ? ", SOLVER=" : "", solver ? solver : "");
            for (size_t i = 0; i < nn; ++i) {
                if (w[(size_t)k * nn + i] != 0) {
                    char v[32];
                printf("%zu, %d, %s\n", i + 1, s + 1, coordinate(w[(size_t)k * nn + i], v, sizeof v));
                }
            }
            printf("*NODE PRINT, NSET=OUT\nU\n*NODE PRINT, NSET=FIXED, TOTALS=ONLY\nRF\n*END STEP\n");
        }
    }
}

static int write_deck(const options *o, const tf_problem *p, const tf_tet10_mesh *q)
{
    double *weight = calloc(q->nn + 1, sizeof *weight);
    unsigned char *fixed = calloc(q->nn + 1, 1), *out = calloc(q->nn + 1, 1);
    if (!weight || !fixed || !out || fixed_nodes(q, p, fixed) != 0) {
        free(weight);
        free(fixed);
        free(out);
        return 2;
    }
    const tf_patch *pt = &p->contacts[0].patch;
    double area = o->n_sites ? 1 : patch_loads(q, p, pt, weight);
    double want = o->n_sites ? 1 : pt->shape == TF_PATCH_RECT ? pt->size[0] * pt->size[1] : pt->area;
    if (!(fabs(area - want) <= 1e-9 * want)) {
        fprintf(stderr, "organ_deck: the loaded faces' area %.12g differs from the patch's %.12g\n",
                area, want);
        free(weight);
        free(fixed);
        free(out);
        return 1;
    }
    size_t nfixed = 0;
    for (size_t i = 0; i < q->nn; ++i) {
        nfixed += fixed[i];
    }
    printf("** %s: CalculiX deck of tests/calculix/organ_deck.c (spacing %g mm, graded to %g mm "
           "near the contact, refine %u)\n",
           o->scene, o->spacing, o->grade > 0 ? o->grade : o->spacing, o->refine);
    printf("** SIZE %zu %zu %zu\n", q->ntet, q->nn, 3 * (q->nn - nfixed));
    double *sw = o->n_sites ? calloc((size_t)o->n_sites * q->nn, sizeof *sw) : NULL;
    int rc = o->n_sites ? (sw ? site_loads(o, p, q, sw, out) : 1) : write_outputs(q, p, out) ? 2 : 0;
    if (rc != 0) {
        free(sw);
        free(weight);
        free(fixed);
        free(out);
        return rc;
    }
    write_mesh(q);
    write_set("FIXED", fixed, q->nn);
    write_set("OUT", out, q->nn);
    printf("*BOUNDARY\nFIXED, 1, 3\n");
    write_material(o, "TISSUE", &p->material);
    printf("*SOLID SECTION, ELSET=ORGAN, MATERIAL=TISSUE\n");
    for (size_t k = 0; k < p->n_inclusions; ++k) {
        char name[32];
        snprintf(name, sizeof name, "INC%zu", k + 1);
        write_material(o, name, &p->inclusions[k].material);
        printf("*SOLID SECTION, ELSET=INC%zu, MATERIAL=INC%zu\n", k + 1, k + 1);
    }
    if (o->n_sites) {
        write_site_steps(o, sw, q->nn, o->solver);
    } else if (o->nlgeom) {
        write_nlgeom_step(o, weight, q->nn, area);
    } else {
        write_steps(p, weight, q->nn, area, o->solver);
    }
    free(sw);
    free(weight);
    free(fixed);
    free(out);
    return fflush(stdout) == 0 ? 0 : 1;
}

int main(int argc, char **argv)
{
    options o = {0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    if (parse(argc, argv, &o) != 0) {
        return usage();
    }
    tf_scene *sc = tf_scene_load(&ctx, o.scene, NULL, 0);
    if (sc == NULL) {
        fprintf(stderr, "organ_deck: %s\n", ctx.err);
        return 2;
    }
    const tf_problem *p = &sc->problem;
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    if (o.nlgeom && strcmp(tf_material_name(&p->material), "neo-hookean") != 0) {
        fprintf(stderr, "organ_deck: %s: --nlgeom writes a neo-Hookean scene's deck (this one is %s)\n",
                o.scene, tf_material_name(&p->material));
        tf_scene_free(sc);
        return 2;
    }
    int shape = p->n_contacts ? (int)p->contacts[0].patch.shape : -1;
    int region = p->n_contacts && p->contacts[0].region.kind == TF_CONTACT_REGION_ORGAN;
    if (m ? (o.n_sites ? !region : shape != TF_PATCH_SURFACE)
          : shape != TF_PATCH_RECT || !(o.quantum > 0) || o.n_sites) {
        fprintf(stderr, "organ_deck: %s: needs an organ with a contact site, an organ with a "
                        "contact region and --sites, or a box with a rectangular patch and "
                        "--quantum\n", o.scene);
        tf_scene_free(sc);
        return 2;
    }
    for (int k = 0; k < o.n_sites; ++k) { /* before the mesh is made */
        const double *ab = o.sites + 2 * k, *len = p->contacts[0].region.chart.len;
        if (!(ab[0] >= 0 && ab[0] <= len[0] && ab[1] >= 0 && ab[1] <= len[1])) {
            fprintf(stderr, "organ_deck: --sites: (%g, %g) is outside the region's domain "
                            "[0, %g] x [0, %g]\n", ab[0], ab[1], len[0], len[1]);
            tf_scene_free(sc);
            return 2;
        }
    }
    tf_surface s = {0};
    tf_tet10_mesh q;
    tf_geom_msg msg;
    tf_mesh_options mo = m ? m->mesh : (tf_mesh_options){0};
    mo.spacing = o.spacing;
    mo.graded = o.grade > 0;
    if (mo.graded && m && o.n_sites == 1) { /* a region's one site: its surface point */
        const tf_region_chart *ch = &p->contacts[0].region.chart;
        double qs[3] = {o.sites[0], o.sites[1], 0};
        if (tf_region_chart_height(ch, qs[0], qs[1], &qs[2]) != 0) {
            fprintf(stderr, "organ_deck: --sites: no surface over (%g, %g)\n", qs[0], qs[1]);
            tf_scene_free(sc);
            return 2;
        }
        tf_region_chart_point(ch, qs, mo.grade_at);
    } else if (mo.graded && m) {
        memcpy(mo.grade_at, m->tm.xyz + 3 * (size_t)p->contacts[0].node, sizeof mo.grade_at);
    } else if (mo.graded) { /* the patch's centre */
        const tf_patch *pt = &p->contacts[0].patch;
        tf_cloud c = p->cloud;
        int u, v;
        tf_face_axes(pt->face, &u, &v);
        mo.grade_at[tf_face_axis(pt->face)] = tf_cloud_face_coord(&c, pt->face);
        mo.grade_at[u] = pt->centre[0];
        mo.grade_at[v] = pt->centre[1];
    }
    if (mo.graded) {
        mo.grade_spacing = o.grade;
        const double *sz = p->contacts[0].patch.size; /* a box's patch: its half-diagonal */
        mo.grade_radius = m ? 20 : 0.5 * sqrt(sz[0] * sz[0] + sz[1] * sz[1]) + o.grade;
        mo.grade_ramp = m ? 60 : mo.grade_radius + 2 * o.spacing;
    }
    tf_surface skin[TF_INCLUSIONS_MAX];
    tf_mesh_inner inner[TF_INCLUSIONS_MAX];
    if (inclusion_surfaces(&o, p, skin, inner) != 0) {
        tf_scene_free(sc);
        return 2;
    }
    patch_field pf = {&o, &p->contacts[0].region};
    int rc = (m ? surface_of(m, &s) : box_surface(p, o.quantum, &s)) != 0 ? 1 : 0;
    if (rc == 0 && o.patch_refine > 0) { /* the file's triangles split on their own planes */
        rc = tf_surface_refine(&s, patch_size, &pf, TF_MESH_SKIN_RATIO, TF_MESH_MAX_SKIN_VERTICES, &msg);
        if (rc == 0) {
            printf("** PATCH-REFINE %g: %zu skin vertices (the file's %zu)\n", o.patch_refine,
                   s.nv, m->file_nv);
        }
    }
    rc = rc != 0 ? rc : tf_volume_mesh_tet10(&s, &mo, inner, p->n_inclusions, o.refine, &q, &msg);
    if (rc != 0 && (m || s.xyz)) { /* box_surface says why it failed */
        fprintf(stderr, "organ_deck: %s\n", rc == 1 && s.xyz == NULL ? "out of memory" : msg.error);
    } else {
        rc = write_deck(&o, p, &q);
        tf_tet10_mesh_free(&q);
    }
    tf_surface_free(&s);
    for (size_t k = 0; k < p->n_inclusions; ++k) {
        tf_surface_free(&skin[k]);
    }
    tf_scene_free(sc);
    return rc;
}
