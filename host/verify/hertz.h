/*
 * hertz.h — the Hertz test of seed 004 §3 (GUIDE §5 "hertz") for the MLS
 * collocation solver: a rigid sphere of radius R pressed into a block, the
 * force at each indentation d against F = 4/3 E* sqrt(R) d^(3/2) (eq 13),
 * 1/E* = (1 - nu^2)/E (eq 14, rigid indenter).
 *
 * The block is a quarter of [-L, L]^2 x [-L, 0] with mirror planes x = 0
 * and y = 0, bottom and sides clamped (seed 004's FEBio set-up), particles
 * on nested grids with Voronoi volumes (hertz_cloud.h).  Each indentation
 * is a static answer (dynamic relaxation) continued from the previous one;
 * the force is the quarter's times 4.  The indentation error is measured as
 * seed 004 measures it, at the force: the theory's indentation for the
 * computed force, d_th(F) = (3F / (4 E* sqrt R))^(2/3), against d.
 */
#ifndef TF_HERTZ_H
#define TF_HERTZ_H

#include <stddef.h>

#include "base/context.h"
#include "solvers/collocation/colloc.h"

#define TF_HERTZ_MAX_INDENT 16

typedef struct tf_hertz_opts {
    const tf_law_ops *law; /* a registered law with parameters E and nu */
    double young, nu;    /* MPa, - */
    double radius;       /* R, mm */
    double core;         /* L0: half-width of the finest grid's box, mm */
    int cells;           /* grid cells across each level's box */
    int levels;          /* nested grids; the block's half-width is L0 ratio^(levels-1) */
    double ratio;        /* spacing from one level to the next */
    int seed_volumes;    /* 1: eqs 2-3 volumes instead of the Voronoi ones */
    double indent[TF_HERTZ_MAX_INDENT]; /* d / R, ascending */
    size_t n_indent;
    double tol;          /* of the relaxation */
    tf_colloc_opts colloc;
} tf_hertz_opts;

/* The defaults of docs/collocation.md: linear law, E = 1 MPa, nu = 0.3,
 * R = 100 mm, L0 = 5 mm, 8 cells, 7 levels of ratio 2 (4,353 particles,
 * L = 320 mm), d/R = 1e-4, 2.5e-4, 4e-4, 6.25e-4 (a = 1 .. 2.5 mm). */
void tf_hertz_defaults(tf_hertz_opts *o);

typedef struct tf_hertz_row {
    size_t particles, images;
    double h0, L;                 /* mm */
    double d, a;                  /* indentation and sqrt(R d), mm */
    double F, F_theory, d_theory; /* N, N, mm */
    size_t contacts, steps;
    double seconds;
} tf_hertz_row;

/* Runs every indentation on one cloud; rows[k] for indent[k].  Returns 0,
 * or -1 with the message in ctx (bad options, a relaxation that fails). */
int tf_hertz_run(const tf_hertz_opts *o, tf_hertz_row *rows, tf_ctx *ctx);

/* Relative L2 norms over the rows of F - F_theory and d - d_theory, and the
 * largest |d / d_theory - 1|. */
void tf_hertz_errors(const tf_hertz_row *rows, size_t n, double *l2_force, double *l2_indent,
                     double *worst);

#endif /* TF_HERTZ_H */
