/*
 * scene_schema.c — libcyaml schema of scene files (scene_schema.h).
 * Enumerations are strict: only their names are accepted, not numbers.
 */
#include "scene/scene_schema.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "materials/material.h"
#include "problem/problem.h"

#define OPT CYAML_FLAG_OPTIONAL
#define OPT_PTR (CYAML_FLAG_OPTIONAL | CYAML_FLAG_POINTER)
#define STRICT_OPT (CYAML_FLAG_OPTIONAL | CYAML_FLAG_STRICT)

static const cyaml_schema_value_t real = {CYAML_VALUE_FLOAT(CYAML_FLAG_DEFAULT, double)};
static const cyaml_schema_value_t count = {CYAML_VALUE_UINT(CYAML_FLAG_DEFAULT, unsigned)};
static const cyaml_schema_value_t node_number = {CYAML_VALUE_UINT(CYAML_FLAG_DEFAULT, uint32_t)};

static const cyaml_strval_t faces[] = {
    {"x-", TF_FACE_XMIN}, {"x+", TF_FACE_XMAX}, {"y-", TF_FACE_YMIN},
    {"y+", TF_FACE_YMAX}, {"z-", TF_FACE_ZMIN}, {"z+", TF_FACE_ZMAX},
};
static const cyaml_strval_t axes[] = {{"x", 0}, {"y", 1}, {"z", 2}};
static const cyaml_strval_t components[] = {{"x", TF_COMP_X}, {"y", TF_COMP_Y}, {"z", TF_COMP_Z}};
static const cyaml_strval_t shapes[] = {
    {"face", TF_PATCH_FACE}, {"rect", TF_PATCH_RECT}, {"circle", TF_PATCH_CIRCLE}};
static const cyaml_strval_t tips[] = {{"disc", TF_TIP_DISC}, {"rect", TF_TIP_RECT}};
static const cyaml_strval_t selects[] = {
    {"all", TF_OUT_ALL},         {"face", TF_OUT_FACE},
    {"box", TF_OUT_BOX},         {"nodes", TF_OUT_NODES},
    {"contact", TF_OUT_CONTACT}, {"points", TF_OUT_POINTS},
    {"surface", TF_OUT_SURFACE}, {"near-contact", TF_OUT_NEAR_CONTACT},
    {"vertices", TF_OUT_VERTICES},
};
static const cyaml_strval_t centres[] = {{"point", TF_SUPPORT_POINT}, {"cell", TF_SUPPORT_CELL}};
static const cyaml_strval_t polynomials[] = {{"none", 0}, {"linear", 1}};
static const cyaml_strval_t volumetrics[] = {{"full", TF_VOLUMETRIC_FULL},
                                             {"cell", TF_VOLUMETRIC_CELL}};
static const cyaml_strval_t bcs[] = {
    {"elimination", TF_BC_ELIMINATION}, {"penalty", TF_BC_PENALTY}, {"nitsche", TF_BC_NITSCHE}};
static const cyaml_strval_t integrations[] = {{"gauss", TF_INTEGRATION_GAUSS},
                                              {"vci", TF_INTEGRATION_VCI}};
/* tf_ordering values (solvers/cholmod_solve.h) */
static const cyaml_strval_t orderings[] = {{"default", 0}, {"amd", 1}, {"metis", 2}, {"nesdis", 3}};
static const cyaml_strval_t tangents[] = {{"full", TF_TANGENT_FULL},
                                          {"modified", TF_TANGENT_MODIFIED},
                                          {"krylov", TF_TANGENT_KRYLOV},
                                          {"bfgs", TF_TANGENT_BFGS},
                                          {"patch", TF_TANGENT_PATCH}};
static const cyaml_strval_t indefinites[] = {{"ldl", TF_INDEFINITE_LDL},
                                             {"shift", TF_INDEFINITE_SHIFT}};
static const cyaml_strval_t references[] = {{"cantilever", TF_ANALYTIC_CANTILEVER},
                                            {"linear", TF_ANALYTIC_LINEAR}};

#define N(a) CYAML_ARRAY_LEN(a)

static const cyaml_schema_field_t box_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("min", CYAML_FLAG_DEFAULT, sd_box, min, &real, 3),
    CYAML_FIELD_SEQUENCE_FIXED("max", CYAML_FLAG_DEFAULT, sd_box, max, &real, 3),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t rotate_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("axis", CYAML_FLAG_DEFAULT, sd_rotate, axis, &real, 3),
    CYAML_FIELD_FLOAT("angle", CYAML_FLAG_DEFAULT, sd_rotate, angle),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t surface_fields[] = {
    CYAML_FIELD_STRING_PTR("file", CYAML_FLAG_DEFAULT, sd_surface, file, 1, 511),
    CYAML_FIELD_FLOAT_PTR("scale", OPT, sd_surface, scale),
    CYAML_FIELD_BOOL_PTR("centre", OPT, sd_surface, centre),
    CYAML_FIELD_MAPPING_PTR("rotate", OPT, sd_surface, rotate, rotate_fields),
    CYAML_FIELD_SEQUENCE_FIXED("translate", OPT_PTR, sd_surface, translate, &real, 3),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t refine_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("at", OPT_PTR, sd_refine, at, &real, 3),
    CYAML_FIELD_FLOAT("spacing", CYAML_FLAG_DEFAULT, sd_refine, spacing),
    CYAML_FIELD_FLOAT("radius", CYAML_FLAG_DEFAULT, sd_refine, radius),
    CYAML_FIELD_FLOAT("ramp", CYAML_FLAG_DEFAULT, sd_refine, ramp),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t geometry_fields[] = {
    CYAML_FIELD_MAPPING_PTR("box", OPT, sd_geometry, box, box_fields),
    CYAML_FIELD_SEQUENCE_FIXED("grid", OPT_PTR, sd_geometry, grid, &count, 3),
    CYAML_FIELD_SEQUENCE_FIXED("grading", OPT_PTR, sd_geometry, grading, &real, 3),
    CYAML_FIELD_FLOAT_PTR("jitter", OPT, sd_geometry, jitter),
    CYAML_FIELD_UINT_PTR("seed", OPT, sd_geometry, seed),
    CYAML_FIELD_MAPPING_PTR("surface", OPT, sd_geometry, surface, surface_fields),
    CYAML_FIELD_FLOAT_PTR("spacing", OPT, sd_geometry, spacing),
    CYAML_FIELD_MAPPING_PTR("refine", OPT, sd_geometry, refine, refine_fields),
    CYAML_FIELD_BOOL_PTR("refine_skin", OPT, sd_geometry, refine_skin),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t plane_fields[] = {
    CYAML_FIELD_ENUM("axis", CYAML_FLAG_STRICT, sd_plane, axis, axes, N(axes)),
    CYAML_FIELD_FLOAT("at", CYAML_FLAG_DEFAULT, sd_plane, at),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t ellipsoid_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("centre", CYAML_FLAG_DEFAULT, sd_ellipsoid, centre, &real, 3),
    CYAML_FIELD_SEQUENCE_FIXED("radii", CYAML_FLAG_DEFAULT, sd_ellipsoid, radii, &real, 3),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t sphere_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("centre", CYAML_FLAG_DEFAULT, sd_sphere, centre, &real, 3),
    CYAML_FIELD_FLOAT("radius", CYAML_FLAG_DEFAULT, sd_sphere, radius),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t side_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("point", CYAML_FLAG_DEFAULT, sd_side, point, &real, 3),
    CYAML_FIELD_SEQUENCE_FIXED("normal", CYAML_FLAG_DEFAULT, sd_side, normal, &real, 3),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t near_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("point", CYAML_FLAG_DEFAULT, sd_near, point, &real, 3),
    CYAML_FIELD_FLOAT("distance", CYAML_FLAG_DEFAULT, sd_near, distance),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t site_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("point", CYAML_FLAG_DEFAULT, sd_site, point, &real, 3),
    CYAML_FIELD_FLOAT("radius", CYAML_FLAG_DEFAULT, sd_site, radius),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t fixed_fields[] = {
    CYAML_FIELD_ENUM_PTR("face", STRICT_OPT, sd_fixed, face, faces, N(faces)),
    CYAML_FIELD_MAPPING_PTR("plane", OPT, sd_fixed, plane, plane_fields),
    CYAML_FIELD_MAPPING_PTR("box", OPT, sd_fixed, box, box_fields),
    CYAML_FIELD_MAPPING_PTR("sphere", OPT, sd_fixed, sphere, sphere_fields),
    CYAML_FIELD_MAPPING_PTR("side", OPT, sd_fixed, side, side_fields),
    CYAML_FIELD_MAPPING_PTR("near", OPT, sd_fixed, near, near_fields),
    CYAML_FIELD_SEQUENCE("vertices", OPT_PTR, sd_fixed, vertices, &node_number, 0,
                         CYAML_UNLIMITED),
    CYAML_FIELD_FLAGS_PTR("components", STRICT_OPT, sd_fixed, components, components,
                          N(components)),
    CYAML_FIELD_SEQUENCE_FIXED("displacement", OPT_PTR, sd_fixed, displacement, &real, 3),
    CYAML_FIELD_BOOL_PTR("exact", OPT, sd_fixed, exact),
    CYAML_FIELD_END,
};
static const cyaml_schema_value_t fixed_entry = {
    CYAML_VALUE_MAPPING(CYAML_FLAG_DEFAULT, sd_fixed, fixed_fields)};

static const cyaml_schema_field_t patch_fields[] = {
    CYAML_FIELD_ENUM("face", CYAML_FLAG_STRICT, sd_patch, face, faces, N(faces)),
    CYAML_FIELD_ENUM_PTR("shape", STRICT_OPT, sd_patch, shape, shapes, N(shapes)),
    CYAML_FIELD_SEQUENCE_FIXED("centre", OPT_PTR, sd_patch, centre, &real, 2),
    CYAML_FIELD_SEQUENCE_FIXED("size", OPT_PTR, sd_patch, size, &real, 2),
    CYAML_FIELD_FLOAT_PTR("radius", OPT, sd_patch, radius),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t load_fields[] = {
    CYAML_FIELD_UINT_PTR("node", OPT, sd_load, node),
    CYAML_FIELD_SEQUENCE_FIXED("at", OPT_PTR, sd_load, at, &real, 3),
    CYAML_FIELD_MAPPING_PTR("patch", OPT, sd_load, patch, patch_fields),
    CYAML_FIELD_MAPPING_PTR("site", OPT, sd_load, site, site_fields),
    CYAML_FIELD_SEQUENCE_FIXED("force", OPT_PTR, sd_load, force, &real, 3),
    CYAML_FIELD_BOOL_PTR("exact", OPT, sd_load, exact),
    CYAML_FIELD_END,
};
static const cyaml_schema_value_t load_entry = {
    CYAML_VALUE_MAPPING(CYAML_FLAG_DEFAULT, sd_load, load_fields)};

static const cyaml_schema_field_t region_fields[] = {
    CYAML_FIELD_ENUM_PTR("face", STRICT_OPT, sd_region, face, faces, N(faces)),
    CYAML_FIELD_SEQUENCE_FIXED("rect", OPT_PTR, sd_region, rect, &real, 4),
    CYAML_FIELD_SEQUENCE_FIXED("centre", OPT_PTR, sd_region, centre, &real, 3),
    CYAML_FIELD_FLOAT_PTR("radius", OPT, sd_region, radius),
    CYAML_FIELD_SEQUENCE_FIXED("size", OPT_PTR, sd_region, size, &real, 2),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t tip_fields[] = {
    CYAML_FIELD_ENUM_PTR("shape", STRICT_OPT, sd_tip, shape, tips, N(tips)),
    CYAML_FIELD_FLOAT_PTR("radius", OPT, sd_tip, radius),
    CYAML_FIELD_SEQUENCE_FIXED("size", OPT_PTR, sd_tip, size, &real, 2),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t contact_fields[] = {
    CYAML_FIELD_STRING_PTR("name", OPT, sd_contact, name, 1, TF_PROBLEM_NAME_MAX - 1),
    CYAML_FIELD_UINT_PTR("node", OPT, sd_contact, node),
    CYAML_FIELD_SEQUENCE_FIXED("at", OPT_PTR, sd_contact, at, &real, 3),
    CYAML_FIELD_MAPPING_PTR("patch", OPT, sd_contact, patch, patch_fields),
    CYAML_FIELD_MAPPING_PTR("site", OPT, sd_contact, site, site_fields),
    CYAML_FIELD_MAPPING_PTR("region", OPT, sd_contact, region, region_fields),
    CYAML_FIELD_MAPPING_PTR("tip", OPT, sd_contact, tip, tip_fields),
    CYAML_FIELD_FLOAT_PTR("friction", OPT, sd_contact, friction),
    CYAML_FIELD_FLOAT_PTR("spacing", OPT, sd_contact, spacing),
    CYAML_FIELD_END,
};
static const cyaml_schema_value_t contact_entry = {
    CYAML_VALUE_MAPPING(CYAML_FLAG_DEFAULT, sd_contact, contact_fields)};

static const cyaml_schema_field_t envelope_fields[] = {
    CYAML_FIELD_FLOAT_PTR("radius", OPT, sd_envelope, radius),
    CYAML_FIELD_SEQUENCE_FIXED("centre", OPT_PTR, sd_envelope, centre, &real, 3),
    CYAML_FIELD_END,
};

static const cyaml_schema_value_t point = {
    CYAML_VALUE_SEQUENCE_FIXED(CYAML_FLAG_DEFAULT, double, &real, 3)};

static const cyaml_schema_field_t lattice_fields[] = {
    CYAML_FIELD_SEQUENCE_FIXED("min", CYAML_FLAG_DEFAULT, sd_lattice, min, &real, 3),
    CYAML_FIELD_SEQUENCE_FIXED("max", CYAML_FLAG_DEFAULT, sd_lattice, max, &real, 3),
    CYAML_FIELD_SEQUENCE_FIXED("count", CYAML_FLAG_DEFAULT, sd_lattice, count, &count, 3),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t outputs_fields[] = {
    CYAML_FIELD_ENUM("select", CYAML_FLAG_STRICT, sd_outputs, select, selects, N(selects)),
    CYAML_FIELD_ENUM_PTR("face", STRICT_OPT, sd_outputs, face, faces, N(faces)),
    CYAML_FIELD_MAPPING_PTR("box", OPT, sd_outputs, box, box_fields),
    CYAML_FIELD_SEQUENCE("nodes", OPT_PTR, sd_outputs, nodes, &node_number, 0, CYAML_UNLIMITED),
    CYAML_FIELD_SEQUENCE("points", OPT_PTR, sd_outputs, points, &point, 1, CYAML_UNLIMITED),
    CYAML_FIELD_MAPPING_PTR("lattice", OPT, sd_outputs, lattice, lattice_fields),
    CYAML_FIELD_FLOAT_PTR("radius", OPT, sd_outputs, radius),
    CYAML_FIELD_SEQUENCE("vertices", OPT_PTR, sd_outputs, vertices, &node_number, 0,
                         CYAML_UNLIMITED),
    CYAML_FIELD_END,
};

static const cyaml_schema_value_t xy_entry = {
    CYAML_VALUE_SEQUENCE_FIXED(CYAML_FLAG_DEFAULT, double, &real, 2)};

static const cyaml_schema_field_t cut_fields[] = {
    CYAML_FIELD_SEQUENCE("path", CYAML_FLAG_POINTER, sd_cut, path, &xy_entry, 2,
                         TF_CUT_MAX_POINTS),
    CYAML_FIELD_FLOAT("depth", CYAML_FLAG_DEFAULT, sd_cut, depth),
    CYAML_FIELD_END,
};
static const cyaml_schema_value_t cut_entry = {
    CYAML_VALUE_MAPPING(CYAML_FLAG_DEFAULT, sd_cut, cut_fields)};

static const cyaml_schema_field_t rbf_fields[] = {
    CYAML_FIELD_FLOAT_PTR("alpha_c", OPT, sd_rbf, alpha_c),
    CYAML_FIELD_FLOAT_PTR("d_c", OPT, sd_rbf, d_c),
    CYAML_FIELD_FLOAT_PTR("spacings", OPT, sd_rbf, spacings),
    CYAML_FIELD_FLOAT_PTR("q", OPT, sd_rbf, q),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t colloc_fields[] = {
    CYAML_FIELD_UINT_PTR("neighbours", OPT, sd_colloc, neighbours),
    CYAML_FIELD_FLOAT_PTR("support", OPT, sd_colloc, support),
    CYAML_FIELD_FLOAT_PTR("stabilisation", OPT, sd_colloc, stabilisation),
    CYAML_FIELD_FLOAT_PTR("volume_constant", OPT, sd_colloc, volume_constant),
    CYAML_FIELD_FLOAT_PTR("density", OPT, sd_colloc, density),
    CYAML_FIELD_FLOAT_PTR("damping", OPT, sd_colloc, damping),
    CYAML_FIELD_FLOAT_PTR("tolerance", OPT, sd_colloc, tolerance),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t newton_fields[] = {
    CYAML_FIELD_FLOAT_PTR("tolerance", OPT, sd_newton, tolerance),
    CYAML_FIELD_FLOAT_PTR("energy_tolerance", OPT, sd_newton, energy_tolerance),
    CYAML_FIELD_UINT_PTR("iterations", OPT, sd_newton, iterations),
    CYAML_FIELD_UINT_PTR("steps", OPT, sd_newton, steps),
    CYAML_FIELD_UINT_PTR("cuts", OPT, sd_newton, cuts),
    CYAML_FIELD_ENUM_PTR("tangent", STRICT_OPT, sd_newton, tangent, tangents, N(tangents)),
    CYAML_FIELD_UINT_PTR("krylov_iterations", OPT, sd_newton, krylov_iterations),
    CYAML_FIELD_FLOAT_PTR("patch_radius", OPT, sd_newton, patch_radius),
    CYAML_FIELD_ENUM_PTR("indefinite", STRICT_OPT, sd_newton, indefinite, indefinites,
                         N(indefinites)),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t solver_fields[] = {
    CYAML_FIELD_STRING_PTR("method", OPT, sd_solver, method, 1, TF_SOLVER_METHOD_MAX - 1),
    CYAML_FIELD_FLOAT_PTR("support", OPT, sd_solver, support),
    CYAML_FIELD_ENUM_PTR("centre", STRICT_OPT, sd_solver, centre, centres, N(centres)),
    CYAML_FIELD_MAPPING_PTR("rbf", OPT, sd_solver, rbf, rbf_fields),
    CYAML_FIELD_ENUM_PTR("polynomial", STRICT_OPT, sd_solver, polynomial, polynomials,
                         N(polynomials)),
    CYAML_FIELD_ENUM_PTR("volumetric", STRICT_OPT, sd_solver, volumetric, volumetrics,
                         N(volumetrics)),
    CYAML_FIELD_SEQUENCE_FIXED("cells", OPT_PTR, sd_solver, cells, &count, 3),
    CYAML_FIELD_UINT_PTR("gauss", OPT, sd_solver, gauss),
    CYAML_FIELD_UINT_PTR("tet_degree", OPT, sd_solver, tet_degree),
    CYAML_FIELD_ENUM_PTR("bc", STRICT_OPT, sd_solver, bc, bcs, N(bcs)),
    CYAML_FIELD_FLOAT_PTR("penalty", OPT, sd_solver, penalty),
    CYAML_FIELD_FLOAT_PTR("nitsche", OPT, sd_solver, nitsche),
    CYAML_FIELD_ENUM_PTR("integration", STRICT_OPT, sd_solver, integration, integrations,
                         N(integrations)),
    CYAML_FIELD_ENUM_PTR("ordering", STRICT_OPT, sd_solver, ordering, orderings, N(orderings)),
    CYAML_FIELD_MAPPING_PTR("newton", OPT, sd_solver, newton, newton_fields),
    CYAML_FIELD_FLOAT_PTR("rcond_warn", OPT, sd_solver, rcond_warn),
    CYAML_FIELD_MAPPING_PTR("collocation", OPT, sd_solver, collocation, colloc_fields),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t reference_fields[] = {
    CYAML_FIELD_ENUM("kind", CYAML_FLAG_STRICT, sd_reference, kind, references, N(references)),
    CYAML_FIELD_FLOAT_PTR("load", OPT, sd_reference, load),
    CYAML_FIELD_SEQUENCE_FIXED("offset", OPT_PTR, sd_reference, offset, &real, 3),
    CYAML_FIELD_SEQUENCE_FIXED("gradient", OPT_PTR, sd_reference, gradient, &real, 9),
    CYAML_FIELD_END,
};

static const cyaml_strval_t segment_kinds[] = {
    {"step", TF_SEG_STEP}, {"release", TF_SEG_RELEASE}, {"ramp", TF_SEG_RAMP},
    {"hold", TF_SEG_HOLD}, {"sinusoid", TF_SEG_SINUSOID}};

static const cyaml_schema_field_t segment_fields[] = {
    CYAML_FIELD_ENUM("kind", CYAML_FLAG_STRICT, sd_segment, kind, segment_kinds, N(segment_kinds)),
    CYAML_FIELD_FLOAT_PTR("to", OPT, sd_segment, to),
    CYAML_FIELD_FLOAT_PTR("time", OPT, sd_segment, time),
    CYAML_FIELD_FLOAT_PTR("amplitude", OPT, sd_segment, amplitude),
    CYAML_FIELD_FLOAT_PTR("period", OPT, sd_segment, period),
    CYAML_FIELD_END,
};
static const cyaml_schema_value_t segment_entry = {
    CYAML_VALUE_MAPPING(CYAML_FLAG_DEFAULT, sd_segment, segment_fields)};

static const cyaml_schema_field_t history_fields[] = {
    CYAML_FIELD_FLOAT("dt", CYAML_FLAG_DEFAULT, sd_history, dt),
    CYAML_FIELD_FLOAT("duration", CYAML_FLAG_DEFAULT, sd_history, duration),
    CYAML_FIELD_SEQUENCE_FIXED("force", OPT_PTR, sd_history, force, &real, 3),
    CYAML_FIELD_STRING_PTR("contact", OPT, sd_history, contact, 1, TF_PROBLEM_NAME_MAX - 1),
    CYAML_FIELD_SEQUENCE("segments", OPT_PTR, sd_history, segments, &segment_entry, 1,
                         CYAML_UNLIMITED),
    CYAML_FIELD_STRING_PTR("table", OPT, sd_history, table, 1, 4095),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t fit_fields[] = {
    CYAML_FIELD_STRING_PTR("family", OPT, sd_fit, family, 1, 32),
    CYAML_FIELD_STRING_PTR("contact", OPT, sd_fit, contact, 1, TF_PROBLEM_NAME_MAX - 1),
    CYAML_FIELD_UINT_PTR("train", OPT, sd_fit, train),
    CYAML_FIELD_UINT_PTR("heldout", OPT, sd_fit, heldout),
    CYAML_FIELD_UINT_PTR("seed", OPT, sd_fit, seed),
    CYAML_FIELD_UINT_PTR("folds", OPT, sd_fit, folds),
    CYAML_FIELD_UINT_PTR("max_degree", OPT, sd_fit, max_degree),
    CYAML_FIELD_UINT_PTR("max_rank", OPT, sd_fit, max_rank),
    CYAML_FIELD_UINT_PTR("servo_hz", OPT, sd_fit, servo_hz),
    CYAML_FIELD_UINT_PTR("tick_us", OPT, sd_fit, tick_us),
    CYAML_FIELD_UINT_PTR("histories", OPT, sd_fit, histories),
    CYAML_FIELD_UINT_PTR("heldout_histories", OPT, sd_fit, heldout_histories),
    CYAML_FIELD_UINT_PTR("history_ticks", OPT, sd_fit, history_ticks),
    CYAML_FIELD_UINT_PTR("solve_every", OPT, sd_fit, solve_every),
    CYAML_FIELD_UINT_PTR("cut_intervals", OPT, sd_fit, cut_intervals),
    CYAML_FIELD_UINT_PTR("cut_heldout", OPT, sd_fit, cut_heldout),
    CYAML_FIELD_END,
};

static const cyaml_schema_field_t scene_fields[] = {
    CYAML_FIELD_STRING_PTR("name", OPT, sd_scene, name, 1, TF_PROBLEM_NAME_MAX - 1),
    CYAML_FIELD_MAPPING("geometry", CYAML_FLAG_DEFAULT, sd_scene, geometry, geometry_fields),
    /* its fields come from the law registry (sd_schema_init) */
    CYAML_FIELD_MAPPING("material", CYAML_FLAG_DEFAULT, sd_scene, material, NULL),
    /* its entries' schema is built with the material's (sd_schema_init) */
    CYAML_FIELD_SEQUENCE("inclusions", OPT_PTR, sd_scene, inclusions, NULL, 0, TF_INCLUSIONS_MAX),
    CYAML_FIELD_SEQUENCE("fixed", CYAML_FLAG_POINTER, sd_scene, fixed, &fixed_entry, 1,
                         CYAML_UNLIMITED),
    CYAML_FIELD_SEQUENCE("loads", OPT_PTR, sd_scene, loads, &load_entry, 0, CYAML_UNLIMITED),
    CYAML_FIELD_SEQUENCE("contact", OPT_PTR, sd_scene, contact, &contact_entry, 0,
                         CYAML_UNLIMITED),
    CYAML_FIELD_MAPPING_PTR("envelope", OPT, sd_scene, envelope, envelope_fields),
    CYAML_FIELD_MAPPING("outputs", CYAML_FLAG_DEFAULT, sd_scene, outputs, outputs_fields),
    CYAML_FIELD_SEQUENCE("cuts", OPT_PTR, sd_scene, cuts, &cut_entry, 0, CYAML_UNLIMITED),
    CYAML_FIELD_MAPPING_PTR("solver", OPT, sd_scene, solver, solver_fields),
    CYAML_FIELD_MAPPING_PTR("reference", OPT, sd_scene, reference, reference_fields),
    CYAML_FIELD_MAPPING_PTR("history", OPT, sd_scene, history, history_fields),
    CYAML_FIELD_MAPPING_PTR("fit", OPT, sd_scene, fit, fit_fields),
    CYAML_FIELD_END,
};

_Static_assert(N(scene_fields) == SD_SCENE_KEYS + 1, "SD_SCENE_KEYS counts scene_fields");

/* material: law, a name the registry knows (scene_build.c looks it up), and
 * every parameter key of every law, each a number into its slot. */
static void material_fields(cyaml_schema_field_t *f, size_t nkeys)
{
    static const cyaml_schema_field_t law =
        CYAML_FIELD_STRING_PTR("law", OPT, sd_material, law, 1, 63);
    static const cyaml_schema_field_t param =
        CYAML_FIELD_FLOAT_PTR("", OPT, sd_material, param[0]);
    static const cyaml_schema_field_t end = CYAML_FIELD_END;
    f[0] = law;
    for (size_t k = 0; k < nkeys; ++k) {
        f[1 + k] = param;
        f[1 + k].key = tf_law_key_at(k);
        f[1 + k].data_offset += (uint32_t)(k * sizeof(double *));
    }
    f[1 + nkeys] = end;
}

int sd_schema_init(sd_schema *s)
{
    size_t nkeys = tf_law_key_count();
    if (nkeys > SD_MATERIAL_KEYS) {
        return -1;
    }
    memcpy(s->scene, scene_fields, sizeof scene_fields);
    const cyaml_schema_field_t inclusion[] = {
        CYAML_FIELD_STRING_PTR("name", OPT, sd_inclusion, name, 1, TF_INCLUSION_NAME_MAX - 1),
        CYAML_FIELD_MAPPING_PTR("sphere", OPT, sd_inclusion, sphere, sphere_fields),
        CYAML_FIELD_MAPPING_PTR("ellipsoid", OPT, sd_inclusion, ellipsoid, ellipsoid_fields),
        CYAML_FIELD_MAPPING_PTR("box", OPT, sd_inclusion, box, box_fields),
        CYAML_FIELD_MAPPING("material", CYAML_FLAG_DEFAULT, sd_inclusion, material, s->material),
        CYAML_FIELD_END,
    };
    _Static_assert(sizeof inclusion == sizeof s->inclusion, "sd_schema.inclusion holds them");
    memcpy(s->inclusion, inclusion, sizeof inclusion);
    s->inclusion_entry = (cyaml_schema_value_t){
        CYAML_VALUE_MAPPING(CYAML_FLAG_DEFAULT, sd_inclusion, s->inclusion)};
    for (size_t k = 0; k < SD_SCENE_KEYS; ++k) {
        if (strcmp(s->scene[k].key, "material") == 0) {
            s->scene[k].value.mapping.fields = s->material;
        } else if (strcmp(s->scene[k].key, "inclusions") == 0) {
            s->scene[k].value.sequence.entry = &s->inclusion_entry;
        }
    }
    material_fields(s->material, nkeys);
    s->root = (cyaml_schema_value_t){
        CYAML_VALUE_MAPPING(CYAML_FLAG_POINTER, sd_scene, s->scene)};
    return 0;
}

static void collect(cyaml_log_t level, void *ctx, const char *fmt, va_list args)
{
    sd_log *log = ctx;
    if (log == NULL || level < CYAML_LOG_ERROR || log->len + 1 >= sizeof log->text) {
        return;
    }
    int n = vsnprintf(log->text + log->len, sizeof log->text - log->len, fmt, args);
    if (n > 0) {
        log->len += (size_t)n;
        if (log->len >= sizeof log->text) {
            log->len = sizeof log->text - 1;
        }
    }
}

cyaml_config_t sd_config(sd_log *log)
{
    cyaml_config_t c = {
        .log_fn = collect,
        .log_ctx = log,
        .mem_fn = cyaml_mem,
        .log_level = CYAML_LOG_ERROR,
        .flags = CYAML_CFG_NO_ALIAS,
    };
    return c;
}

void sd_scene_free(const cyaml_schema_value_t *root, sd_scene *doc)
{
    cyaml_config_t c = sd_config(NULL);
    cyaml_free(&c, root, doc, 0);
}

int sd_path_split(char *buf, char **comp)
{
    int n = 0;
    char *save = NULL;
    for (char *tok = strtok_r(buf, ".", &save); tok != NULL; tok = strtok_r(NULL, ".", &save)) {
        if (n == SD_PATH_MAX) {
            return -1;
        }
        comp[n++] = tok;
    }
    return n > 0 ? n : -1;
}

const cyaml_schema_field_t *sd_field(const cyaml_schema_value_t *mapping, const char *key)
{
    if (mapping->type != CYAML_MAPPING) {
        return NULL;
    }
    for (const cyaml_schema_field_t *f = mapping->mapping.fields; f->key != NULL; ++f) {
        if (strcmp(f->key, key) == 0) {
            return f;
        }
    }
    return NULL;
}

const cyaml_schema_value_t *sd_schema_at(const cyaml_schema_value_t *root, const char *path)
{
    char buf[256], *comp[SD_PATH_MAX];
    snprintf(buf, sizeof buf, "%s", path);
    int n = sd_path_split(buf, comp);
    const cyaml_schema_value_t *v = root;
    for (int k = 0; k < n && v != NULL; ++k) {
        if (v->type == CYAML_SEQUENCE || v->type == CYAML_SEQUENCE_FIXED) {
            char *end;
            strtoul(comp[k], &end, 10);
            v = *end == '\0' && comp[k][0] != '\0' ? v->sequence.entry : NULL;
        } else {
            const cyaml_schema_field_t *f = sd_field(v, comp[k]);
            v = f ? &f->value : NULL;
        }
    }
    return n > 0 ? v : NULL;
}

void sd_names(const cyaml_schema_value_t *v, char *out, size_t outlen)
{
    size_t len = 0;
    out[0] = '\0';
    if (v->type == CYAML_MAPPING) {
        for (const cyaml_schema_field_t *f = v->mapping.fields; f->key && len < outlen; ++f) {
            len += (size_t)snprintf(out + len, outlen - len, "%s%s", len ? ", " : "", f->key);
        }
    } else if (v->type == CYAML_ENUM || v->type == CYAML_FLAGS) {
        for (uint32_t k = 0; k < v->enumeration.count && len < outlen; ++k) {
            len += (size_t)snprintf(out + len, outlen - len, "%s%s", len ? ", " : "",
                                    v->enumeration.strings[k].str);
        }
    }
}
