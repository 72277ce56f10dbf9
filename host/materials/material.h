/*
 * material.h — a material law and its parameters, as a problem carries it:
 * a tagged union, one member per law.  Linear isotropic elasticity today;
 * a new law (St Venant-Kirchhoff, neo-Hookean, Kelvin viscoelastic) adds an
 * enumerator, a member of the union and its name in tf_material_name, and
 * solvers say which kinds they accept (docs/architecture.md).
 */
#ifndef TF_MATERIAL_H
#define TF_MATERIAL_H

typedef enum tf_material_kind {
    TF_MATERIAL_LINEAR_ELASTIC, /* small strain, isotropic (elasticity.h) */
} tf_material_kind;

/* Isotropic moduli: Young's modulus E (MPa) and Poisson's ratio nu. */
typedef struct tf_isotropic {
    double young;
    double poisson;
} tf_isotropic;

typedef struct tf_material {
    tf_material_kind kind;
    union {
        tf_isotropic linear; /* TF_MATERIAL_LINEAR_ELASTIC */
    } as;
} tf_material;

/* "linear elastic" */
static inline const char *tf_material_name(tf_material_kind kind)
{
    switch (kind) {
    case TF_MATERIAL_LINEAR_ELASTIC:
        return "linear elastic";
    }
    return "unknown";
}

#endif /* TF_MATERIAL_H */
