/*
 * problem.h — a problem: everything a solver needs to compute displacements,
 * and nothing about where it came from.  Geometry and its node cloud,
 * material, fixed regions (resolved to nodes), loads, contact sites, the
 * force envelope, the output nodes, the solver's options and an optional
 * analytic solution.  Every value has been checked by whoever built it
 * (host/scene/ builds one from YAML; a test may fill one by hand).  Units:
 * mm, N, MPa.
 *
 * Node numbering (1-based numbers, GUIDE §5 extended to every layer): on a
 * box grid of nx × ny × nz nodes, node (i, j, k) with k = 0 at the bottom has
 * number N = i + nx j + nx ny (nz - 1 - k) + 1, so the top layer comes first
 * and block48's node 61 is the top centre.  On an organ's mesh the surface
 * vertices come first, in the order tissuefit reads the file
 * (geometry/surface_read.h), then the interior nodes.  Internal node index
 * = N - 1 everywhere in host/.
 */
#ifndef TF_PROBLEM_H
#define TF_PROBLEM_H

#include <stddef.h>
#include <stdint.h>

#include "geometry/tetmesh.h"
#include "geometry/transform.h"
#include "geometry/volume_mesh.h"
#include "materials/material.h"
#include "problem/contact_region.h"
#include "problem/history.h"
#include "problem/nodes.h"

#define TF_PROBLEM_NAME_MAX 64

/* Displacement components, as a bit mask. */
enum { TF_COMP_X = 1, TF_COMP_Y = 2, TF_COMP_Z = 4, TF_COMP_ALL = 7 };

/* The body.  A tagged union: a box filled with a grid of nodes, or an
 * organ: a closed surface mesh filled with tetrahedra (problem/mesh_geometry.h). */
typedef enum tf_geometry_kind { TF_GEOMETRY_BOX, TF_GEOMETRY_MESH } tf_geometry_kind;

typedef struct tf_box_geometry {
    double min[3], max[3]; /* mm */
    unsigned grid[3];      /* nodes per axis */
    double jitter;         /* fraction of the spacing, interior nodes */
    uint64_t seed;         /* of the jitter */
    tf_cloud_grading grading;    /* ratio 1 on every axis: a uniform grid (nodes.h) */
} tf_box_geometry;

/* An organ (TF_GEOMETRY_MESH): the surface file, how it is placed and
 * filled, and the result.  Nodes 0 .. tm.nsurf - 1 are the surface
 * vertices (the renderer's mesh), interior nodes follow; the tetrahedra
 * are the integration cells. */
typedef struct tf_mesh_geometry {
    char file[512];         /* as the scene names it */
    char path[1024];        /* as opened (relative to the scene's folder) */
    uint32_t file_crc32;    /* of the file's bytes */
    tf_transform place;     /* file units and frame -> scene mm */
    tf_mesh_options mesh;   /* interior spacing and grading */
    tf_tetmesh tm;
    double *file_xyz;       /* 3 file_nv: the file's vertices in its frame and units */
    size_t file_nv;         /* the file's vertices: nodes 0 .. file_nv - 1 (the refined
                               skin's midpoints, when mesh.refine_skin, follow them) */
    size_t file_nt;         /* the file's triangles ... */
    size_t *file_tri;       /* 3 file_nt: ... as node indices (tm.tri_parent indexes them) */
    double min_winding;     /* smallest winding number of an interior node (1 when none) */
    char notes[1024];       /* repairs made while reading, one per line */
} tf_mesh_geometry;

/* Frees what g owns (its tetrahedra and file-frame vertices), not g itself;
 * here with the type rather than in mesh_geometry.c, so that tf_problem_release
 * does not reach up into the organ builder. */
void tf_problem_mesh_free(tf_mesh_geometry *g);

typedef struct tf_geometry {
    tf_geometry_kind kind;
    union {
        tf_box_geometry box;     /* TF_GEOMETRY_BOX */
        tf_mesh_geometry *mesh;  /* TF_GEOMETRY_MESH (owned) */
    } as;
} tf_geometry;

typedef enum tf_region_kind {
    TF_REGION_FACE,
    TF_REGION_PLANE,
    TF_REGION_BOX,
    TF_REGION_SPHERE,   /* every node within radius of centre */
    TF_REGION_SIDE,     /* every node on the side of a plane its normal points to */
    TF_REGION_NEAR,     /* surface vertices within radius of centre (meshes) */
    TF_REGION_VERTICES, /* surface vertices named by their index in the mesh file (meshes) */
} tf_region_kind;

/* A set of nodes: a face of the box, a plane x_axis = at, a box, a ball, a
 * half-space, surface vertices near a point or named in a list. */
typedef struct tf_region {
    tf_region_kind kind;
    tf_face face;   /* TF_REGION_FACE */
    int axis;       /* TF_REGION_PLANE: 0, 1, 2 */
    double at;      /* TF_REGION_PLANE, mm */
    double min[3];  /* TF_REGION_BOX, mm */
    double max[3];
    double centre[3]; /* SPHERE, NEAR: centre; SIDE: a point of the plane, mm */
    double normal[3]; /* SIDE */
    double radius;    /* SPHERE, NEAR, mm */
} tf_region;

/* A material region (an inclusion: a nodule, a vessel): a ball, an
 * ellipsoid (axes along x, y, z) or a box of the body with its own material; where inclusions overlap the first
 * listed holds.  Its law is the body's (scene_build.c), its parameters its own.  */
#define TF_INCLUSIONS_MAX 8
#define TF_INCLUSION_NAME_MAX 32
typedef struct tf_inclusion {
    char name[TF_INCLUSION_NAME_MAX];
    tf_region where;      /* TF_REGION_SPHERE (an ellipsoid: radii) or TF_REGION_BOX */
    double radii[3];      /* SPHERE: the semi-axes along x, y, z, mm (a ball: all radius) */
    tf_material material;
} tf_inclusion;

typedef struct tf_fixed {
    tf_region where;
    unsigned components; /* TF_COMP_* mask of the prescribed components */
    double value[3];     /* prescribed displacement, mm */
    int exact;           /* value taken from the problem's analytic solution */
    uint32_t *nodes;     /* resolved node indices, ascending */
    size_t n_nodes;
} tf_fixed;

typedef enum tf_patch_shape {
    TF_PATCH_POINT,  /* a force at one node */
    TF_PATCH_FACE,   /* uniform traction over a whole face */
    TF_PATCH_RECT,   /* uniform traction over a rectangle of a face */
    TF_PATCH_CIRCLE, /* uniform traction over a disc of a face */
    TF_PATCH_SURFACE,/* uniform traction over surface triangles of a mesh (a contact site) */
    TF_PATCH_AT,     /* a force at a point anywhere in the body, spread to the nodes by
                        their shape functions there (the Galerkin load of a point force) */
    TF_PATCH_POINTS, /* uniform traction over an area given by its quadrature points (a
                        probe's patch clipped from an organ's surface, region_chart.h) */
} tf_patch_shape;

/* Where a force acts.  In-face coordinates (u, v): (x, y) on z faces,
 * (y, z) on x faces, (x, z) on y faces. */
typedef struct tf_patch {
    tf_patch_shape shape;
    uint32_t node;      /* TF_PATCH_POINT: node index */
    tf_face face;       /* the other shapes */
    double centre[2];   /* RECT, CIRCLE: (u, v), mm */
    double size[2];     /* RECT: side lengths along u and v, mm */
    double radius;      /* CIRCLE, SURFACE, mm */
    double at[3];       /* AT: the point; SURFACE: the site's centre (a surface vertex), mm */
    uint32_t *tri;      /* SURFACE: 3 node indices per triangle, outward (owned) */
    size_t n_tri;
    double area;        /* SURFACE: their total area; POINTS: the weights' sum, mm^2 */
    double *pts;        /* POINTS: 4 per point: x, y, z (mm) and weight (mm^2) (owned) */
    size_t n_pts;
} tf_patch;

/* Frees what a patch owns (its triangles or points) and clears them. */
void tf_patch_release(tf_patch *p);

/* A load that is always applied: a total force spread over a patch, or the
 * analytic solution's traction (exact). */
typedef struct tf_load {
    tf_patch patch;
    double force[3]; /* N, total over the patch */
    int exact;
} tf_load;

/* A contact site: where the haptic force acts, and the point whose
 * displacement is the contact displacement.  Given by a node number, the
 * point is that node and its displacement the nodal value; given by
 * position (or by its patch, whose centre it then is), the displacement is
 * the solver's field at the point, whatever the grid. */
typedef struct tf_contact {
    char name[TF_PROBLEM_NAME_MAX];
    uint32_t node;  /* node index: the node given, or the node nearest `at` */
    double at[3];   /* the contact point, mm */
    int by_node;    /* 1: given as a node number (the nodal value is the contact displacement) */
    tf_patch patch; /* TF_PATCH_POINT at `node` (TF_PATCH_AT at `at`) when no patch was given */
    /* A region (kind != NONE): the tool may touch anywhere on it.  Point,
     * node and patch are then those of the probe at the region's centre,
     * so that what fits one site still has one. */
    tf_contact_region region;
} tf_contact;

/* The forces the haptic device may apply: the ball |F - centre| <= radius. */
typedef struct tf_envelope {
    double radius;    /* N */
    double centre[3]; /* N */
} tf_envelope;

typedef enum tf_output_kind {
    TF_OUT_ALL,
    TF_OUT_FACE,
    TF_OUT_BOX,
    TF_OUT_NODES,
    TF_OUT_CONTACT,
    TF_OUT_POINTS,
    TF_OUT_SURFACE,      /* every surface vertex of a mesh */
    TF_OUT_NEAR_CONTACT, /* surface vertices within a radius of a contact site */
    TF_OUT_VERTICES,     /* surface vertices named by their index in the mesh file */
} tf_output_kind;

/* The output points: nodes, or (points != NULL) points anywhere in the
 * body whose displacements are the solver's field there (solvers/probe.h);
 * nodes[] then holds the node nearest each point. */
typedef struct tf_outputs {
    tf_output_kind kind;
    uint32_t *nodes; /* resolved node indices (ascending, or in list order for TF_OUT_NODES) */
    size_t n_nodes;  /* output count */
    double *points;  /* NULL, or 3 n_nodes coordinates, mm */
} tf_outputs;

#define TF_CUT_MAX_POINTS 16
#define TF_CUT_WHERE_MAX 160

/* An incision (meshfree/cut.h): a polyline of n >= 2 points (x, y) on the
 * top surface z = top, swept down by depth.  where names its entry for
 * messages ("scene.yaml:14: cuts.0", or "--set ...: cuts.0"; "" when the
 * cut did not come from a scene). */
typedef struct tf_cut {
    size_t n;
    double xy[TF_CUT_MAX_POINTS][2]; /* mm */
    double top, depth;                /* mm */
    char where[TF_CUT_WHERE_MAX];
} tf_cut;

/* Essential conditions: nodal values removed (RPIM), the seed's penalty
 * (RPIM: eq 28 on nodal values; EFG: the weak form of seed 001 eqs 19, 23),
 * or Nitsche's method (solvers/boundary.h). */
typedef enum tf_bc_method { TF_BC_ELIMINATION, TF_BC_PENALTY, TF_BC_NITSCHE } tf_bc_method;
typedef enum tf_support_centre { TF_SUPPORT_POINT, TF_SUPPORT_CELL } tf_support_centre;
typedef enum tf_volumetric { TF_VOLUMETRIC_FULL, TF_VOLUMETRIC_CELL } tf_volumetric;
/* Volume integration: Gauss points as they are, or with the shape-function
 * gradients corrected per cell so that the discrete divergence theorem
 * holds (VCI, solvers/cell_gradients.h). */
typedef enum tf_integration { TF_INTEGRATION_GAUSS, TF_INTEGRATION_VCI } tf_integration;

#define TF_SOLVER_METHOD_MAX 32

/* The MLS collocation solver's options (solvers/collocation/, scene
 * solver.collocation; docs/collocation.md). */
typedef struct tf_colloc_settings {
    unsigned neighbours;    /* k nearest (ties at the k-th distance included) */
    double support;         /* support radius / mean neighbour distance */
    double stabilisation;   /* weight of the fit-residual energy */
    double volume_constant; /* k_v of [Aras-MLS] eq 12, MPa */
    double density;         /* t/mm^3 (1e-9: 1000 kg/m^3) */
    double damping;         /* mass-proportional damping of load histories, 1/s */
    double tolerance;       /* of the dynamic relaxation (relative residual) */
} tf_colloc_settings;

/* How the nonlinear solver solves each Newton iteration's linear system
 * (docs/solver.md): a new factorisation of the tangent every iteration; the
 * last factorisation kept until convergence slows (modified Newton); a
 * Krylov method (CG, or GMRES for an unsymmetric tangent) on the current
 * tangent preconditioned by the last factorisation, refactorised when the
 * Krylov iterations exceed krylov_max; or quasi-Newton (limited-memory
 * BFGS) updates of the last factorisation, refactorised when they stall;
 * or BFGS whose factor is kept up to date near the contact sites (the
 * patch tangent: the DOFs within patch_radius of a contact site ordered
 * last, their block of the factor refreshed every iteration). */
typedef enum tf_tangent_kind {
    TF_TANGENT_FULL,
    TF_TANGENT_MODIFIED,
    TF_TANGENT_KRYLOV,
    TF_TANGENT_BFGS,
    TF_TANGENT_PATCH,
} tf_tangent_kind;

/* What a Cholesky factorisation that finds the tangent not positive
 * definite does next (solvers/nonlinear/nl_linear.c): an LDL^T
 * factorisation of the tangent itself (Newton's method follows the path
 * past a limit point, onto unstable equilibria too), or a Cholesky
 * factorisation of the tangent with its diagonal raised by a factor
 * 1 + sigma, the least of 1e-3 x 4^k that is positive definite (the
 * iterates go downhill in energy: to a stable equilibrium, across a snap). */
typedef enum tf_indefinite_kind {
    TF_INDEFINITE_LDL,
    TF_INDEFINITE_SHIFT,
} tf_indefinite_kind;

/* Newton-Raphson and load stepping (solvers/nonlinear/). */
typedef struct tf_newton_opts {
    double rtol;         /* |residual| <= rtol |internal forces| ... */
    double etol;         /* ... and |du . residual| <= etol of the step's first */
    unsigned max_iter;   /* iterations per load step */
    unsigned steps;      /* load steps to begin with */
    unsigned max_cuts;   /* halvings of a load step before giving up */
    tf_tangent_kind tangent;
    unsigned krylov_max; /* Krylov iterations per solve before refactorising */
    double patch_radius; /* mm: the patch tangent's DOFs, around each contact site */
    tf_indefinite_kind indefinite;
} tf_newton_opts;

/* Which solver (by its registered name, solvers/solver.h) and how it
 * discretises.  The meshless options are those of the RPIM Galerkin solver;
 * a solver ignores what it does not use. */
/* The most background cells a scene may ask for (solver.cells' product). */
#define TF_SOLVER_MAX_CELLS 1000000

typedef struct tf_solver_opts {
    char method[TF_SOLVER_METHOD_MAX]; /* registered solver name, e.g. "rpim-galerkin" */
    double support;   /* alpha_s: support radius in nodal spacings (per axis) */
    tf_support_centre centre; /* support centred at each Gauss point or at its cell */
    double alpha_c;   /* RBF: R(r) = (r^2 + (alpha_c d_c)^2)^q   (seed eq 12) */
    double d_c;       /* mm, when d_c_spacings is 0 (absolute, the seed's) */
    double d_c_spacings; /* > 0: d_c = d_c_spacings x the local nodal spacing (meshfree/shape.h) */
    double q;
    int polynomial;   /* 0: none (seed eq 12); 1: linear augmentation (seed eq 11) */
    tf_volumetric volumetric; /* volumetric strain at each Gauss point, or per cell (B-bar) */
    unsigned cells[3];/* background cells per axis */
    unsigned gauss;   /* Gauss-Legendre points per axis per cell */
    unsigned tet_degree; /* meshes: degree of the Gauss rule on each tetrahedron (1, 2, 5) */
    tf_bc_method bc;
    double penalty;   /* lambda of seed eq 28 (RPIM); alpha / ((lambda + 2 mu) / h) (EFG) */
    double nitsche;   /* Nitsche's beta / ((lambda + 2 mu) / h) */
    tf_integration integration;
    double rcond_warn;/* warn when a local system's reciprocal condition is below */
    tf_colloc_settings colloc; /* "mls-collocation" */
    int ordering;     /* fill-reducing ordering, tf_ordering (solvers/cholmod_solve.h) */
    tf_newton_opts newton; /* nonlinear laws */
} tf_solver_opts;

typedef enum tf_analytic_kind {
    TF_ANALYTIC_NONE,
    TF_ANALYTIC_CANTILEVER,
    TF_ANALYTIC_LINEAR,
} tf_analytic_kind;

/* An analytic solution the problem is checked against (analytic.h). */
typedef struct tf_analytic {
    tf_analytic_kind kind;
    double load;         /* CANTILEVER: end load P per mm of thickness, N/mm (+y; plane strain) */
    double offset[3];    /* LINEAR: u(x) = offset + gradient x, mm */
    double gradient[9];  /* LINEAR: row-major du_i/dx_j */
} tf_analytic;

typedef struct tf_problem {
    char name[TF_PROBLEM_NAME_MAX];
    char source[512];   /* where it came from (a scene file), for messages */
    tf_geometry geometry;
    tf_cloud cloud;     /* the nodes */
    tf_material material; /* a law and its parameters (materials/material.h): the body's, */
    tf_inclusion inclusions[TF_INCLUSIONS_MAX]; /* but for these parts of it */
    size_t n_inclusions;
    tf_fixed *fixed;
    size_t n_fixed;
    tf_load *loads;
    size_t n_loads;
    tf_contact *contacts;
    size_t n_contacts;
    tf_envelope envelope;
    tf_outputs outputs;
    tf_cut *cuts;       /* incisions; a solver without TF_SOLVER_CUTS refuses them */
    size_t n_cuts;
    tf_solver_opts solver;
    tf_analytic analytic;
    tf_history history;   /* how the loads change in time (present: 0 when not given) */
} tf_problem;

/* Frees what the problem owns (cloud, fixed nodes, loads, contacts, outputs)
 * and zeroes it; the struct itself belongs to the caller. */
void tf_problem_release(tf_problem *p);

/* Index of the contact site called name, or -1. */
int tf_problem_contact(const tf_problem *p, const char *name);

/* The organ of a mesh problem, or NULL. */
static inline const tf_mesh_geometry *tf_problem_mesh(const tf_problem *p)
{
    return p->geometry.kind == TF_GEOMETRY_MESH ? p->geometry.as.mesh : NULL;
}

/* The 1-based node number of a node index (the numbering above). */
static inline uint32_t tf_problem_node_number(const tf_problem *p, size_t index)
{
    (void)p;
    return (uint32_t)index + 1;
}

/* The centre of a patch on its face (a point force: its point), mm. */
void tf_problem_patch_centre(const tf_patch *patch, const tf_cloud *c, double x[3]);

/* Index of the node nearest x (the lowest index of equally near ones). */
uint32_t tf_problem_nearest_node(const tf_problem *p, const double x[3]);

/* The geometry's bounding box, mm. */
void tf_problem_bounds(const tf_problem *p, double lo[3], double hi[3]);

/* Marks the DOFs (3 i + a) a fixed region prescribes: mask[dof] = 1, else
 * 0; mask holds 3 cloud.n entries. */
void tf_problem_fixed_dofs(const tf_problem *p, unsigned char *mask);

/* 1 when the response to a contact force is linear, not only affine: no
 * load always acts and every prescribed displacement is zero. */
int tf_problem_unloaded(const tf_problem *p);

#endif /* TF_PROBLEM_H */
