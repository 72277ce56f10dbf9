/*
 * scene.h — a scene as C data: geometry and its node cloud, material, fixed
 * regions, loads, contact sites, force envelope, outputs (resolved to node
 * indices), solver options and an optional analytic reference solution.
 *
 * A scene is read from a YAML file (docs/scene-format.md) with `--set
 * key=value` overrides applied before validation; every value here has been
 * checked (finite, in range, regions that hold nodes).  Units: mm, N, MPa.
 *
 * Node numbering (1-based scene numbers, GUIDE §5 extended to every layer):
 * on a box grid of nx × ny × nz nodes, node (i, j, k) with k = 0 at the
 * bottom has number N = i + nx j + nx ny (nz - 1 - k) + 1, so the top layer
 * comes first and block48's node 61 is the top centre.  Internal node index
 * = N - 1 everywhere in host/.
 */
#ifndef TF_SCENE_H
#define TF_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "problem/nodes.h"

#define TF_SCENE_NAME_MAX 64

/* Displacement components, as a bit mask. */
enum { TF_COMP_X = 1, TF_COMP_Y = 2, TF_COMP_Z = 4, TF_COMP_ALL = 7 };

typedef enum tf_region_kind { TF_REGION_FACE, TF_REGION_PLANE, TF_REGION_BOX } tf_region_kind;

/* A set of nodes: a face of the box, a plane x_axis = at, or a box. */
typedef struct tf_region {
    tf_region_kind kind;
    tf_face face;   /* TF_REGION_FACE */
    int axis;       /* TF_REGION_PLANE: 0, 1, 2 */
    double at;      /* TF_REGION_PLANE, mm */
    double min[3];  /* TF_REGION_BOX, mm */
    double max[3];
} tf_region;

typedef struct tf_fixed {
    tf_region where;
    unsigned components; /* TF_COMP_* mask of the prescribed components */
    double value[3];     /* prescribed displacement, mm */
    int exact;           /* value taken from the scene's reference solution */
    uint32_t *nodes;     /* resolved node indices, ascending */
    size_t n_nodes;
} tf_fixed;

typedef enum tf_patch_shape {
    TF_PATCH_POINT,  /* a force at one node */
    TF_PATCH_FACE,   /* uniform traction over a whole face */
    TF_PATCH_RECT,   /* uniform traction over a rectangle of a face */
    TF_PATCH_CIRCLE, /* uniform traction over a disc of a face */
} tf_patch_shape;

/* Where a force acts.  In-face coordinates (u, v): (x, y) on z faces,
 * (y, z) on x faces, (x, z) on y faces. */
typedef struct tf_patch {
    tf_patch_shape shape;
    uint32_t node;      /* TF_PATCH_POINT: node index */
    tf_face face;       /* the other shapes */
    double centre[2];   /* RECT, CIRCLE: (u, v), mm */
    double size[2];     /* RECT: side lengths along u and v, mm */
    double radius;      /* CIRCLE, mm */
} tf_patch;

/* A load that is always applied: a total force spread over a patch, or the
 * reference solution's traction (exact). */
typedef struct tf_load {
    tf_patch patch;
    double force[3]; /* N, total over the patch */
    int exact;
} tf_load;

/* A contact site: where the haptic force acts, and the node whose
 * displacement is the contact displacement. */
typedef struct tf_contact {
    char name[TF_SCENE_NAME_MAX];
    uint32_t node;  /* node index */
    tf_patch patch; /* TF_PATCH_POINT at `node` when the scene names no patch */
} tf_contact;

typedef enum tf_output_kind {
    TF_OUT_ALL,
    TF_OUT_FACE,
    TF_OUT_BOX,
    TF_OUT_NODES,
    TF_OUT_CONTACT,
} tf_output_kind;

typedef struct tf_outputs {
    tf_output_kind kind;
    uint32_t *nodes; /* resolved node indices (ascending, or in list order for TF_OUT_NODES) */
    size_t n_nodes;
} tf_outputs;

typedef enum tf_bc_method { TF_BC_ELIMINATION, TF_BC_PENALTY } tf_bc_method;
typedef enum tf_support_centre { TF_SUPPORT_POINT, TF_SUPPORT_CELL } tf_support_centre;
typedef enum tf_volumetric { TF_VOLUMETRIC_FULL, TF_VOLUMETRIC_CELL } tf_volumetric;

typedef struct tf_solver_opts {
    double support;   /* alpha_s: support radius in nodal spacings (per axis) */
    tf_support_centre centre; /* support centred at each Gauss point or at its cell */
    double alpha_c;   /* RBF: R(r) = (r^2 + (alpha_c d_c)^2)^q   (seed eq 12) */
    double d_c;       /* mm */
    double q;
    int polynomial;   /* 0: none (seed eq 12); 1: linear augmentation (seed eq 11) */
    tf_volumetric volumetric; /* volumetric strain at each Gauss point, or averaged per cell (B-bar) */
    unsigned cells[3];/* background cells per axis */
    unsigned gauss;   /* Gauss-Legendre points per axis per cell */
    tf_bc_method bc;
    double penalty;   /* lambda of seed eq 28 */
    double rcond_warn;/* warn when a local system's reciprocal condition is below */
} tf_solver_opts;

typedef enum tf_reference_kind { TF_REF_NONE, TF_REF_CANTILEVER, TF_REF_LINEAR } tf_reference_kind;

/* Analytic solution a verification scene is checked against. */
typedef struct tf_reference {
    tf_reference_kind kind;
    double load;         /* CANTILEVER: end load P per mm of thickness, N/mm (along +y; plane strain) */
    double offset[3];    /* LINEAR: u(x) = offset + gradient x, mm */
    double gradient[9];  /* LINEAR: row-major du_i/dx_j */
} tf_reference;

/* How `tissuefit fit` samples and fits the scene (docs/fitting.md). */
typedef struct tf_scene_fit {
    int family;             /* forward family to emit (tfit_family: 1 nodal, 2 modal, 3 zhou2017) */
    int contact;            /* contact site index (-1 when the scene has none) */
    unsigned train;         /* training load cases */
    unsigned heldout;       /* held-out load cases, never fitted */
    uint64_t seed;          /* load-case design and folds */
    unsigned folds;         /* k of the k-fold cross-validation */
    unsigned max_degree;    /* polynomial degrees searched */
    unsigned max_rank;      /* modal ranks searched */
} tf_scene_fit;

typedef struct tf_scene {
    char name[TF_SCENE_NAME_MAX];
    char source[512];   /* file the scene came from */

    /* geometry */
    double box_min[3], box_max[3];
    unsigned grid[3];
    double jitter;      /* fraction of the spacing, interior nodes */
    uint64_t seed;
    tf_cloud cloud;     /* the nodes */

    double young;       /* E, MPa */
    double poisson;     /* nu */

    tf_fixed *fixed;
    size_t n_fixed;
    tf_load *loads;
    size_t n_loads;
    tf_contact *contacts;
    size_t n_contacts;
    double envelope_radius;    /* N */
    double envelope_centre[3]; /* N */
    tf_outputs outputs;
    tf_solver_opts solver;
    tf_reference reference;
    tf_scene_fit fit;
} tf_scene;

/* Reads a scene file, applies the overrides ("key=value", e.g.
 * "geometry.grid=41,41,9") in order, validates and resolves it.  Returns
 * NULL with a message naming file, line and field (or the --set argument)
 * in err. */
tf_scene *tf_scene_load(const char *path, const char *const *sets, size_t n_sets, char *err,
                        size_t errlen);

/* The same from YAML text in memory; `name` stands for the file in messages. */
tf_scene *tf_scene_load_text(const char *text, size_t len, const char *name,
                             const char *const *sets, size_t n_sets, char *err, size_t errlen);

void tf_scene_free(tf_scene *s);

/* Index of the contact site called name, or -1. */
int tf_scene_contact(const tf_scene *s, const char *name);

#endif /* TF_SCENE_H */
