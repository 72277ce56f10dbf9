/*
 * scene_schema.h — the scene file as libcyaml loads it: one C struct per
 * YAML mapping, a pointer for every optional value (NULL when absent, so
 * defaults are applied in one place, scene_build.c), and the schema that maps
 * keys to members.  docs/scene-format.md documents each key.
 *
 * Extending the format: add the member here and its field to the mapping's
 * field table in scene_schema.c; `--set` and error locations follow from
 * the schema by themselves.
 */
#ifndef TF_SCENE_SCHEMA_H
#define TF_SCENE_SCHEMA_H

#include <stdbool.h>
#include <stdint.h>

#include <cyaml/cyaml.h>

typedef struct sd_box {
    double min[3];
    double max[3];
} sd_box;

typedef struct sd_rotate {
    double axis[3];
    double angle;      /* degrees */
} sd_rotate;

/* An organ's surface mesh and how it is placed in the scene's frame. */
typedef struct sd_surface {
    char *file;        /* relative to the scene file's folder */
    double *scale;     /* file units -> mm */
    bool *centre;
    sd_rotate *rotate;
    double *translate; /* 3, mm */
} sd_surface;

/* An organ's local refinement (geometry.refine). */
typedef struct sd_refine {
    double *at;        /* 3, mm; default: the first contact site's point */
    double spacing;
    double radius;
    double ramp;
} sd_refine;

typedef struct sd_geometry {
    sd_box *box;       /* a box and its grid, or */
    unsigned *grid;    /* 3 */
    double *grading;   /* 3, a box: largest / smallest spacing per axis */
    double *jitter;
    uint64_t *seed;
    sd_surface *surface; /* an organ's surface, its interior spacing and grading */
    double *spacing;
    sd_refine *refine;
    bool *refine_skin; /* split the surface's triangles to the spacing */
} sd_geometry;

/* Parameter keys over the registered laws (materials/material.h), at
 * most. */
#define SD_MATERIAL_KEYS 16

typedef struct sd_material {
    char *law; /* a registered law's name; the registry's first when absent */
    /* param[k]: the value of key tf_law_key_at(k), NULL when absent */
    double *param[SD_MATERIAL_KEYS];
} sd_material;

typedef struct sd_plane {
    int axis; /* 0 x, 1 y, 2 z */
    double at;
} sd_plane;

typedef struct sd_sphere {
    double centre[3];
    double radius;
} sd_sphere;

typedef struct sd_side {
    double point[3];
    double normal[3];
} sd_side;

typedef struct sd_near {
    double point[3];
    double distance;
} sd_near;

/* A contact site on an organ's surface: a point and a radius. */
typedef struct sd_site {
    double point[3];
    double radius;
} sd_site;

/* A material region: a part of the body (a sphere, an ellipsoid or a box)
 * with its own material. */
typedef struct sd_ellipsoid {
    double centre[3];
    double radii[3];
} sd_ellipsoid;

typedef struct sd_inclusion {
    char *name;
    sd_sphere *sphere;
    sd_ellipsoid *ellipsoid;
    sd_box *box;
    sd_material material;
} sd_inclusion;

typedef struct sd_fixed {
    int *face;        /* tf_face */
    sd_plane *plane;
    sd_box *box;
    sd_sphere *sphere;
    sd_side *side;
    sd_near *near;
    uint32_t *vertices; /* surface vertices by their index in the mesh file */
    unsigned vertices_count;
    unsigned *components; /* TF_COMP_* flags */
    double *displacement; /* 3 */
    bool *exact;
} sd_fixed;

typedef struct sd_patch {
    int face;
    int *shape;      /* tf_patch_shape: face, rect or circle */
    double *centre;  /* 2 */
    double *size;    /* 2 */
    double *radius;
} sd_patch;

typedef struct sd_load {
    uint32_t *node;
    double *at;      /* 3: a point force's position, mm */
    sd_patch *patch;
    sd_site *site;
    double *force;   /* 3 */
    bool *exact;
} sd_load;

/* A contact region: a rectangle of a box face, or of an organ's surface
 * around a point (a square of side 2 radius, or size). */
typedef struct sd_region {
    int *face;       /* tf_face */
    double *rect;    /* 4: a0, a1, b0, b1 (the face's in-face coordinates), mm */
    double *centre;  /* 3, mm */
    double *radius;
    double *size;    /* 2, mm */
} sd_region;

/* The probe's patch around each site of a region. */
typedef struct sd_tip {
    int *shape;      /* tf_tip_shape: disc, rect */
    double *radius;
    double *size;    /* 2, mm */
} sd_tip;

typedef struct sd_contact {
    char *name;
    uint32_t *node;  /* a box: a node, or */
    double *at;      /* 3, a box: the contact point, mm */
    sd_patch *patch;
    sd_site *site;   /* an organ: instead of node and patch */
    sd_region *region; /* instead of all of those: a region */
    sd_tip *tip;       /* a region's probe */
    double *friction;
    double *spacing;   /* a region's site spacing, mm */
} sd_contact;

typedef struct sd_envelope {
    double *radius;
    double *centre;  /* 3 */
} sd_envelope;

typedef struct sd_lattice {
    double min[3], max[3];
    unsigned count[3];
} sd_lattice;

typedef struct sd_outputs {
    int select;      /* tf_output_kind */
    int *face;
    sd_box *box;
    uint32_t *nodes;
    unsigned nodes_count;
    double *radius;      /* near-contact */
    uint32_t *vertices;  /* vertices: indices in the mesh file */
    unsigned vertices_count;
    double (*points)[3];
    unsigned points_count;
    sd_lattice *lattice;
} sd_outputs;

typedef struct sd_rbf {
    double *alpha_c;
    double *d_c;
    double *spacings; /* d_c in local nodal spacings */
    double *q;
} sd_rbf;

typedef struct sd_colloc {
    unsigned *neighbours;
    double *support;
    double *stabilisation;
    double *volume_constant;
    double *density;
    double *damping;
    double *tolerance;
} sd_colloc;

typedef struct sd_newton {
    double *tolerance, *energy_tolerance, *patch_radius;
    unsigned *iterations, *steps, *cuts, *krylov_iterations;
    int *tangent; /* tf_tangent_kind */
    int *indefinite; /* tf_indefinite_kind */
} sd_newton;

typedef struct sd_solver {
    char *method;    /* a registered solver's name (solvers/solver.h) */
    double *support;
    int *centre;     /* tf_support_centre */
    sd_rbf *rbf;
    int *polynomial; /* 0 none, 1 linear */
    int *volumetric; /* tf_volumetric */
    unsigned *cells; /* 3 */
    unsigned *gauss;
    unsigned *tet_degree;
    int *bc;         /* tf_bc_method */
    double *penalty;
    double *nitsche;
    int *integration; /* tf_integration */
    int *ordering;    /* tf_ordering */
    sd_newton *newton;
    double *rcond_warn;
    sd_colloc *collocation; /* "mls-collocation" */
} sd_solver;

typedef struct sd_reference {
    int kind;        /* tf_analytic_kind */
    double *load;
    double *offset;   /* 3 */
    double *gradient; /* 9 */
} sd_reference;

typedef struct sd_xy {
    double v[2];
} sd_xy;

typedef struct sd_cut {
    sd_xy *path;       /* 2 to TF_CUT_MAX_POINTS points (x, y) on the top surface */
    unsigned path_count;
    double depth;
} sd_cut;

typedef struct sd_segment {
    int kind;         /* tf_segment_kind */
    double *to, *time, *amplitude, *period;
} sd_segment;

typedef struct sd_history {
    double dt, duration;
    double *force;    /* 3 */
    char *contact;
    sd_segment *segments;
    unsigned segments_count;
    char *table;      /* CSV file of t, fx, fy, fz */
} sd_history;

typedef struct sd_fit {
    char *family;      /* a registered forward family's name (fitting/families/family.h) */
    char *contact;     /* contact site name */
    unsigned *train, *heldout, *folds, *max_degree, *max_rank, *servo_hz;
    uint64_t *seed;
    /* a time-dependent solver's force histories (fitting/histories.h) */
    unsigned *tick_us, *histories, *heldout_histories, *history_ticks, *solve_every;
    /* cut progress (fitting/cut_progress.h, the cut family) */
    unsigned *cut_intervals, *cut_heldout;
} sd_fit;

typedef struct sd_scene {
    char *name;
    sd_geometry geometry;
    sd_material material;
    sd_inclusion *inclusions;
    unsigned inclusions_count;
    sd_fixed *fixed;
    unsigned fixed_count;
    sd_load *loads;
    unsigned loads_count;
    sd_contact *contact;
    unsigned contact_count;
    sd_envelope *envelope;
    sd_outputs outputs;
    sd_cut *cuts;
    unsigned cuts_count;
    sd_solver *solver;
    sd_reference *reference;
    sd_history *history;
    sd_fit *fit;
} sd_scene;

/* Keys of a scene's top level. */
#define SD_SCENE_KEYS 14

/* The schema of a scene file (a pointer to sd_scene): the fixed keys, and
 * under material the law registry's names and parameter keys.  Built by
 * sd_schema_init; it points into itself, so it is used where it was built
 * and never copied.  Every function below takes its root. */
typedef struct sd_schema {
    cyaml_schema_value_t root;
    cyaml_schema_field_t scene[SD_SCENE_KEYS + 1];
    cyaml_schema_field_t material[SD_MATERIAL_KEYS + 2]; /* law, the keys, the end */
    cyaml_schema_field_t inclusion[6];  /* name, sphere, ellipsoid, box, material, the end */
    cyaml_schema_value_t inclusion_entry;
} sd_schema;

/* Builds the schema.  Returns 0, or -1 when the registry holds more
 * parameter keys than SD_MATERIAL_KEYS (tests/unit/scene checks it never
 * does). */
int sd_schema_init(sd_schema *s);

/* libcyaml's error messages and backtraces, collected for rewording. */
typedef struct sd_log {
    char text[4096];
    size_t len;
} sd_log;

/* Configuration for loading and freeing scene documents; errors go to log
 * (which may be NULL to drop them). */
cyaml_config_t sd_config(sd_log *log);

/* A path names a value in a document: keys and sequence indices joined by
 * dots, as in "material.nu" or "fixed.2.face" (the --set syntax). */
#define SD_PATH_MAX 16

/* Splits a path into at most SD_PATH_MAX components (in buf, which it
 * modifies).  Returns the count, or -1 when empty or too deep. */
int sd_path_split(char *buf, char **comp);

/* The mapping field called key, or NULL. */
const cyaml_schema_field_t *sd_field(const cyaml_schema_value_t *mapping, const char *key);

/* The schema of the value at path below root (NULL when the path names
 * nothing).  Sequence indices are not checked against a document. */
const cyaml_schema_value_t *sd_schema_at(const cyaml_schema_value_t *root, const char *path);

/* "E, nu": the keys of a mapping, or the names of an enumeration. */
void sd_names(const cyaml_schema_value_t *v, char *out, size_t outlen);

/* Frees a document loaded with the schema of root. */
void sd_scene_free(const cyaml_schema_value_t *root, sd_scene *doc);

#endif /* TF_SCENE_SCHEMA_H */
