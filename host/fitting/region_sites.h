/*
 * region_sites.h — the solves behind a contact region's models, for an
 * affine solver: at each site (a point (a, b) of the region's domain) the
 * probe's patch (problem/region_chart.h), its nodal load vectors L_s for
 * unit forces along the chart's axes e1, e2, n (3 columns), solved through
 * the solver's one factorisation as blocks of right-hand sides
 * (tf_solver_solve_loads), and
 *
 *   - the patch-averaged compliance C_s = L_s^T U_s (3 x 3, chart frame,
 *     mm/N): under a uniform traction of resultant F over the patch, the
 *     work-conjugate of F is the patch-averaged displacement l^T u, so
 *     C_s is symmetric (Maxwell-Betti) up to rounding; it is symmetrised
 *     and the largest asymmetry ||C - C^T||_F / ||C||_F is reported;
 *   - the outputs' responses (3 n_out x 3: the scene's outputs, scene
 *     frame, per unit force along each chart axis, mm/N).
 *
 * Each site's L_s is kept (sparse), so that a later load made of any
 * combination of sites' loads can be solved (tf_region_sites_combine):
 * the surface model's site modes need r such solves, not one per site.
 * The problem's own loads, if any, are subtracted (the responses are to
 * the probe's force alone).  Sites are solved in batches; progress goes to
 * the context's log.
 */
#ifndef TF_REGION_SITES_H
#define TF_REGION_SITES_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "problem/problem.h"
#include "solvers/solver.h"

/* A site's load vectors, sparse: the DOFs where any column is non-zero
 * and the three values there. */
typedef struct tf_region_load {
    size_t n;
    uint32_t *dof;
    double *val; /* 3 n: (column 0, 1, 2) per DOF */
} tf_region_load;

typedef struct tf_region_sites {
    size_t n, n_out;
    double *ab;         /* 2 n: chart coordinates, mm */
    double *x;          /* 3 n: the site's surface point, scene frame, mm */
    double *C;          /* 9 n: compliance, chart frame, symmetrised, row-major, mm/N */
    double *U;          /* 9 n_out n: per site 3 n_out x 3, column-major, mm/N */
    tf_region_load *L;  /* n */
    double *seconds;    /* n: wall time each site took (its share of its batch) */
    double asym;        /* largest ||C - C^T||_F / ||C||_F */
    /* Cross compliances recorded while solving (partners, below): for pair
     * k, C(i, j) (3 x 3, row-major, chart frame) is the patch-averaged
     * displacement at site i = pair[2k] per unit force at site j =
     * pair[2k + 1]. */
    size_t n_pairs;
    size_t *pair;
    double *cross;
} tf_region_sites;

/* Solves the n sites ab (2 n) of contact region r of problem p with solver
 * s (affine, built from p).  With partners (may be NULL): for every new
 * site and every partner site within `radius` of it whose tip does not
 * overlap its tip, the cross compliance C(partner, new site) is recorded
 * (reciprocity: L_partner^T U_new, while U_new is at hand); the new sites
 * are counted from partners->n, as when they are appended to partners.
 * Returns 0, or -1 with the message in ctx. */
int tf_region_sites_solve(tf_ctx *ctx, tf_solver *s, const tf_problem *p,
                          const tf_contact_region *r, const double *ab, size_t n,
                          const tf_region_sites *partners, double radius, tf_region_sites *out);

void tf_region_sites_free(tf_region_sites *t);

/* Appends the sites of src to dst (moving its storage; src is emptied). */
int tf_region_sites_append(tf_ctx *ctx, tf_region_sites *dst, tf_region_sites *src);

/* The loads sum_i sum_k coef[(3 i + k) + 3 n_sites j] L_{site[i]} e_k for
 * j = 0 .. ncomb - 1 (site: indices into t, n_sites of them; coef column-
 * major 3 n_sites x ncomb), solved: u (3N x ncomb), the problem's own
 * loads' response subtracted. */
int tf_region_sites_combine(tf_ctx *ctx, tf_solver *s, const tf_region_sites *t,
                            const size_t *site, size_t n_sites, const double *coef, size_t ncomb,
                            double *u);

/* l^T u for site i of t: the patch averages (3, chart frame) of the
 * displacement u (3N). */
void tf_region_sites_average(const tf_region_sites *t, size_t i, const double *u, double out[3]);

/* The chart-axis load vectors of the patch at (a, b), dense (3N x 3,
 * overwritten), and the site's surface point x (may be NULL). */
int tf_region_site_loads(tf_ctx *ctx, const tf_solver *s, const tf_problem *p,
                         const tf_contact_region *r, double a, double b, double *f, double x[3]);

#endif /* TF_REGION_SITES_H */
