/*
 * verify.h — convergence studies of scenes with an analytic reference
 * (`tissuefit verify`): the same scene solved at successive levels, each
 * compared with the reference in the L2 and energy norms.
 *
 * Grid series: level k halves the nodal spacing k times on every axis
 * with more than two nodes, and scales the background cells and the RBF
 * length d_c with it, so every level is the same discretisation at a finer
 * scale.  An axis with two nodes is the thickness of a plane problem: it
 * keeps its two nodes and its extent shrinks with the spacing.
 *
 * Gauss series: level k uses k + 1 Gauss points per axis, nothing else
 * changes.
 */
#ifndef TF_VERIFY_H
#define TF_VERIFY_H

#include <stddef.h>

typedef enum tf_vary { TF_VARY_GRID, TF_VARY_GAUSS } tf_vary;

typedef struct tf_verify_row {
    unsigned level;     /* grid: k; gauss: the Gauss order */
    size_t nodes, dofs;
    double h;           /* nodal spacing along the first refined axis, mm */
    double error_l2, error_energy;
    double rate;        /* of error_l2 against h from the previous row; NAN for the first */
    double seconds;     /* solver build and solve */
} tf_verify_row;

/* Order of the Gauss rule the errors are integrated with. */
#define TF_VERIFY_ERROR_ORDER 5

/* Solves level k of the study of a scene file (with the user's overrides
 * applied first).  Returns 0; -1 with a message for a bad scene (*usage
 * set) or a failed solve. */
int tf_verify_level(const char *scene_path, const char *const *sets, size_t n_sets, tf_vary vary,
                    unsigned k, tf_verify_row *row, int *usage, char *err, size_t errlen);

/* Fills the rate column of rows[1..n) from consecutive rows. */
void tf_verify_rates(tf_verify_row *rows, size_t n);

#endif /* TF_VERIFY_H */
