/*
 * cases.h — the solved load cases behind a fit: training forces filling
 * the envelope, held-out forces never used by a fit (loadcases.h), the
 * displacements of the scene's output points and of the contact site, and
 * single-axis training cases for the zhou2017 family.
 *
 * The solver's response is affine in the force at a contact site (linear
 * elasticity; scene loads add a constant).  So, unless direct solves are
 * asked for, the training displacements come from superposition of the
 * unit responses: one solve with no contact force and three with unit
 * forces span every training case.  Held-out cases are always solved
 * directly, so the held-out error also checks the superposition.  Forces
 * are rounded to float first: the firmware receives float forces, and the
 * comparison is then at exactly the input the target evaluates.
 */
#ifndef TF_FIT_CASES_H
#define TF_FIT_CASES_H

#include <stddef.h>
#include <stdint.h>

#include "fitting/fitdata.h"
#include "scene/scene.h"
#include "solvers/solver.h"

typedef struct tf_cases {
    int contact;             /* contact site index */
    uint32_t contact_node;   /* its node index */
    int superposed;          /* training cases from unit responses */
    size_t solves;           /* right-hand sides solved */
    tf_fitdata train, heldout, axis[3];
    /* Unit responses at the outputs (3 n_out) and the contact site (3):
     * u(f) = base + sum_k f_k unit[k]. */
    double *base, *unit[3], base_contact[3], unit_contact[3][3];
    /* storage behind the tf_fitdata views */
    uint32_t *node_ids;
    double (*rest)[3];
    void *blocks[16];
    int n_blocks;
} tf_cases;

/* Designs and solves the load cases of a fit (n_train >= 6).  direct != 0
 * solves every training case instead of superposing.  Returns 0, or -1
 * with a message. */
int tf_cases_build(const tf_scene *scene, tf_solver *solver, int contact, size_t n_train,
                   size_t n_heldout, uint64_t seed, int direct, tf_cases *c, char *err,
                   size_t errlen);
void tf_cases_free(tf_cases *c);

/* The response to force f by superposition of the unit responses:
 * u (3 n_out) and the contact-site displacement (either may be NULL). */
void tf_cases_response(const tf_cases *c, const double f[3], double *u, double contact[3]);

#endif /* TF_FIT_CASES_H */
