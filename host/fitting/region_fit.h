/*
 * region_fit.h — a contact region's models for an affine solver: the law
 * (P = 2, region_law.h) and the surface (p = 1, region_surface.h) over a
 * grid of sites whose density the held-out error chooses.
 *
 * Site density: the first spacing is the one the scene fixes
 * (contact.K.spacing), or else about the probe's diameter (a disc's 2 r, a
 * rectangle's longer side), with at least TF_SPLINE_MIN_SITES sites per
 * axis (nx = ceil(len / S) + 1; the spacing is len / (nx - 1) <= S).  The
 * models are fitted to the grid's sites and judged at the centres of its
 * cells, sites never fitted, solved for real:
 *
 *   force    max over the cell centres of ||K(g) C_s - I||_2: the law's
 *            force error at the true patch-averaged displacement of the
 *            worst force on the envelope's sphere, as a fraction of its
 *            radius (C_s the solved compliance, K(g) the law's stiffness);
 *   surface  max over the cell centres and outputs of the largest error
 *            of an output's displacement under an envelope force, as a
 *            fraction of the peak: the largest output displacement an
 *            envelope force makes at any site solved (grid and centres);
 *   coupling the two-instrument error the surface's cross compliances
 *            make (spec §5), to first order ||K_i (C_model(i, j) -
 *            C(i, j))||_2 (a fraction of R_F), both ways, over every pair of
 *            a cell centre and a grid site whose tips do not overlap within
 *            TF_REGION_PAIR_REACH tip half-extents (at most
 *            TF_REGION_PAIRS_JUDGED of them, evenly; the true C(i, j) is
 *            recorded while the cell centre's solve is at hand);
 *   height   the largest |h(g) - h| of the spline's rest surface (mm).
 *
 * The rank is the smallest meeting the surface and coupling targets (at
 * most max_rank; searched by doubling, then bisection), else the one of the
 * smallest surface error tried.  Until both targets are met the spacing is halved (every
 * cell centre becomes a site: its solve is reused), up to max_sites per
 * axis; the result says which ended it.  Every site's solve is kept in
 * the result (the study's two-instrument test reuses the loads).
 */
#ifndef TF_REGION_FIT_H
#define TF_REGION_FIT_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/region_law.h"
#include "fitting/region_sites.h"
#include "fitting/region_surface.h"
#include "problem/problem.h"
#include "solvers/solver.h"

typedef struct tf_region_targets {
    double force;       /* fraction of the envelope radius (0.01) */
    double surface;     /* fraction of the peak displacement (0.05) */
    double coupling;    /* fraction of the envelope radius (0.02); INFINITY: measured and
                           stated, not a target (neither the rank nor the spacing is chosen
                           for it: tissuefit fit's device models, region_models.h) */
    unsigned max_sites; /* per axis (the cap) */
    unsigned max_rank;
    unsigned levels;    /* 0: halve until met or capped; k: fit exactly k spacings */
    double near;        /* the surface's near-field radius in probe widths (0: none;
                           region_surface.h) */
    unsigned near_cap;  /* its most outputs per control point */
} tf_region_targets;

/* The spec's targets: force 1 %, surface 5 %, two instruments 2 %; at most
 * 33 sites per axis and TF_REGION_MAX_RANK modes; the near field within 1.5
 * probe widths, at most TF_REGION_MAX_NEAR outputs per control point. */
tf_region_targets tf_region_targets_default(void);

#define TF_REGION_MAX_LEVELS 8

/* Pairs judged for the coupling: sites within this many tip half-extents
 * (the strongly coupled ones: beyond, the coupling and its error fade),
 * every k-th of them so that at most TF_REGION_PAIRS_JUDGED are. */
#define TF_REGION_PAIR_REACH 6.0
#define TF_REGION_PAIRS_JUDGED 4000

typedef struct tf_region_level {
    unsigned nx, ny;
    double h[2];         /* site spacing, mm */
    unsigned rank;
    double force;        /* errors at the cell centres, as defined above */
    double surface;
    double coupling;
    double force_rms;    /* the RMS over the cell centres of each one's force and surface */
    double surface_rms;  /* error (the headers' held-out RMS) */
    size_t pairs;        /* the coupling's pairs of a cell centre and a grid site */
    double height;       /* mm */
    double peak;         /* mm */
    double min_stiffness;/* smallest eigenvalue of K, N/mm: over the control points when all
                            are SPD (cp_spd), else over a sampling of the blend */
    int cp_spd;
    size_t law_floats, surface_floats;
    double seconds;      /* regeneration at this spacing: the solver's set-up, the solves of
                            its sites and cell centres, the fit */
    int met;
    tf_region_law law;   /* the models at this spacing (kept for the study) */
    tf_region_surface surface_model;
    tf_region_modes modes; /* what surfaces of other ranks are cut from */
    size_t *train;       /* nx ny indices into the result's sites, grid order */
    size_t *check;       /* the (nx - 1)(ny - 1) cell centres' indices into them */
    size_t n_check;
} tf_region_level;

typedef struct tf_region_result {
    tf_region_sites sites;  /* every site solved */
    tf_region_level level[TF_REGION_MAX_LEVELS];
    unsigned n_levels;      /* the last is the answer */
    char why[256];          /* "target met at spacing ..." or the cap, with the errors */
} tf_region_result;

/* Fits contact region `contact` of problem p with solver s (affine, from
 * p).  Progress and the verdict go to the context's log.  Returns 0, or
 * -1 with the message. */
int tf_region_fit(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                  const tf_region_targets *tg, tf_region_result *res);

void tf_region_result_free(tf_region_result *res);

/* A surface's error at the cell centres of level lv of res (sites never
 * fitted): the largest and the RMS over them of the largest output error
 * under an envelope force, as fractions of lv's peak displacement. */
void tf_region_surface_heldout(const tf_region_surface *sf, const tf_region_result *res,
                               const tf_region_level *lv, double *max, double *rms);
/* A surface's two-instrument coupling error on level lv's pairs (as the
 * level's own, region_fit.h above), a fraction of R_F. */
double tf_region_surface_coupling(const tf_region_surface *sf, const tf_region_result *res,
                                  const tf_region_level *lv);

/* The law (P = 2) of the nx x ny sites idx (grid order) of t: K_s = C_s^-1
 * symmetrised, in v = s_u u, and the site heights in the chart c. */
int tf_region_law_fit(tf_ctx *ctx, const tf_region_sites *t, const size_t *idx, unsigned nx,
                      unsigned ny, const double h[2], const tf_region_chart *chart, double s_u,
                      double mu, tf_region_law *law);

/* The displacement scale's reciprocal: 1 / (R_F times the largest
 * eigenvalue of the sites' compliances). */
double tf_region_scale(const tf_region_sites *t, const size_t *idx, size_t n, double R_F);
/* The largest output displacement an envelope force (|F| = R_F) makes at
 * sites idx[0..n) of t (idx NULL: the first n): R_F times the largest
 * spectral norm of an output's 3 x 3 response. */
double tf_region_peak(const tf_region_sites *t, const size_t *idx, size_t n, double R_F);

/* Spectral norm of a 3 x 3 matrix. */
double tf_mat3_norm2(const double M[9]);

#endif /* TF_REGION_FIT_H */
