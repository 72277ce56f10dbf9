/*
 * stability_path.c — the stability of block48's equilibria along a contact
 * load path (issue 13, acceptance 5: why the 3 N neo-Hookean case is hard at
 * fine grids), for `make nl-stability`: numbers are printed, never asserted.
 *
 *   stability_path NX,NY,NZ STEPS [force=FX,FY,FZ] [tol=T] [KEY=VALUE...]
 *
 * Loads the top-centre contact site in STEPS equal increments up to force
 * (default 0, 0, -3 N; the neo-Hookean law unless a KEY=VALUE sets another),
 * each step from the last equilibrium (tf_nonlinear_advance), and after each
 * brackets the least eigenvalue mu_1 of K_t v = mu K_0 v to within tol
 * (default 1/64; tf_nonlinear_stability_of): mu_1 <= 0 is an equilibrium at
 * or past a limit or bifurcation point; the contact node's displacement
 * shows which branch the equilibrium is on (u_x = u_y = 0 on the symmetric
 * one).  One CSV row per step on stdout;
 * progress on stderr.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/blas_pin.h"
#include "base/context.h"
#include "scene/scene.h"
#include "solvers/nonlinear/nonlinear.h"
#include "solvers/solver.h"

#define MAX_SETS 16

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct args {
    unsigned grid[3];
    int steps;
    double force[3], tol;
    const char *sets[MAX_SETS];
    size_t ns;
    char set_grid[64], set_node[64];
} args;

static int parse(int argc, char **argv, args *a)
{
    a->force[0] = a->force[1] = 0;
    a->force[2] = -3;
    a->tol = 1.0 / 64;
    a->steps = argc > 2 ? atoi(argv[2]) : 0;
    if (argc < 3 || sscanf(argv[1], "%u,%u,%u", &a->grid[0], &a->grid[1], &a->grid[2]) != 3 ||
        a->steps < 1 || argc - 3 > MAX_SETS - 3) {
        fprintf(stderr, "usage: stability_path NX,NY,NZ STEPS [force=FX,FY,FZ] [tol=T] "
                        "[KEY=VALUE...]\n");
        return 2;
    }
    snprintf(a->set_grid, sizeof a->set_grid, "geometry.grid=%s", argv[1]);
    snprintf(a->set_node, sizeof a->set_node, "contact.0.node=%u",
             a->grid[0] / 2 + a->grid[0] * (a->grid[1] / 2) + 1);
    a->sets[0] = a->set_grid;
    a->sets[1] = a->set_node;
    a->sets[2] = "material.law=neo-hookean";
    a->ns = 3;
    for (int k = 3; k < argc; ++k) {
        if (sscanf(argv[k], "force=%lf,%lf,%lf", &a->force[0], &a->force[1], &a->force[2]) == 3) {
            continue;
        }
        if (sscanf(argv[k], "tol=%lf", &a->tol) == 1) {
            continue;
        }
        a->sets[a->ns++] = argv[k];
    }
    return 0;
}

/* One step: advance to fraction th of the force, then the probe; a row. */
static int step(tf_solver *sv, const args *a, int k, const double *xyz, size_t contact,
                double *u)
{
    double th = (double)k / a->steps, f[3] = {th * a->force[0], th * a->force[1], th * a->force[2]};
    tf_nonlinear_info i0, i1;
    tf_nonlinear_info_of(sv, &i0);
    double c0 = cpu_now();
    if (tf_nonlinear_advance(sv, 1, 0, f, 0) != 0) {
        printf("# step %d (%.4g of the force): %s\n", k, th, sv->ctx->err);
        return -1;
    }
    double c1 = cpu_now();
    tf_nonlinear_info_of(sv, &i1);
    tf_nonlinear_stability st;
    if (tf_nonlinear_stability_of(sv, a->tol, &st) != 0) {
        printf("# step %d: stability: %s\n", k, sv->ctx->err);
        return -1;
    }
    double c2 = cpu_now();
    tf_nonlinear_displacements(sv, u);
    const double *x = xyz + 3 * st.node;
    printf("%.4f,%.4f,%.6f,%.6f,%.6f,%zu,%zu,%zu,%zu,%.6f,%.6f,%.6f,%d,%zu,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f,%zu,%.2f\n", th,
           f[2], u[3 * contact], u[3 * contact + 1], u[3 * contact + 2], i1.iterations - i0.iterations, i1.steps - i0.steps,
           i1.factorisations - i0.factorisations, (i1.kept - i0.kept) + (i1.indefinite - i0.indefinite),
           st.lo, st.hi, st.mu, st.definite, st.node + 1, x[0], x[1], x[2], st.dir[0], st.dir[1],
           st.dir[2], c1 - c0,
           st.factorisations, c2 - c1);
    fflush(stdout);
    fprintf(stderr, "stability_path: %d/%d: mu_1 %.4f (%s) at node %zu, %.1f + %.1f s CPU\n", k,
            a->steps, st.mu, st.definite ? "definite" : "NOT definite", st.node + 1, c1 - c0,
            c2 - c1);
    return 0;
}

int main(int argc, char **argv)
{
    tf_blas_pin(argv); /* the tool's OpenBLAS kernels and one BLAS thread */
    args a;
    int rc = parse(argc, argv, &a);
    if (rc != 0) {
        return rc;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", a.sets, a.ns);
    if (s == NULL) {
        fprintf(stderr, "stability_path: %s\n", ctx.err);
        return 2;
    }
    tf_solver *sv = tf_solver_create(&s->problem, NULL, &ctx);
    double *u = sv ? malloc(3 * s->problem.cloud.n * sizeof *u) : NULL;
    if (u == NULL) {
        fprintf(stderr, "stability_path: %s\n", ctx.err);
        return 1;
    }
    size_t contact = a.grid[0] / 2 + (size_t)a.grid[0] * (a.grid[1] / 2); /* node 1 + this, on top */
    printf("# block48 %s, %s, force (%g, %g, %g) N in %d steps, tol %g\n", a.set_grid,
           a.ns > 3 ? a.sets[3] : "defaults", a.force[0], a.force[1], a.force[2], a.steps, a.tol);
    printf("fraction,fz_N,ux_contact_mm,uy_contact_mm,uz_contact_mm,iterations,load_steps,factorisations,indefinite,"
           "mu_lo,mu_hi,mu,definite,mode_node,mode_x,mode_y,mode_z,mode_dx,mode_dy,mode_dz,"
           "cpu_solve_s,"
           "probe_factorisations,cpu_probe_s\n");
    for (int k = 1; k <= a.steps && rc == 0; ++k) {
        rc = step(sv, &a, k, s->problem.cloud.xyz, contact, u);
    }
    free(u);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return rc == 0 ? 0 : 1;
}
