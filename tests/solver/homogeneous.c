/*
 * homogeneous.c — the homogeneous tests of issue 13 (acceptance 1) as a
 * study: the cube of tests/support/homogeneous.h, RPIM and EFG, against
 * closed forms (make nonlinear-validation writes the tables of
 * docs/validation.md §8).
 *
 *   homogeneous stretch   force against stretch, SVK and neo-Hookean,
 *                         50 % compression and 100 % stretch
 *   homogeneous relax     Kelvin relaxation after a strain step (k = 0, 5)
 *                         and the neo-Hookean Kelvin variant
 *   homogeneous creep     Kelvin creep under a stress step (k = 0, 5), error
 *                         at t = 5 s against the time step
 *
 * CSV on standard output; progress on standard error.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "homogeneous.h"
#include "solvers/nonlinear/nonlinear.h"

static const char *const methods[] = {"rpim-galerkin", "efg-galerkin"};

typedef struct opened {
    tf_ctx ctx;
    tf_scene *s;
    tf_solver *sv;
    double *u;
} opened;

static int open_cube(opened *o, const char *method, const char *mat, int stretch, double lam,
                     double force)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_ctx_init(&o->ctx);
    o->ctx.level = TF_LOG_ERROR;
    o->s = homog_scene(&ctx, method, mat, stretch, lam, force, NULL, 0);
    if (o->s == NULL) {
        fprintf(stderr, "homogeneous: %s\n", ctx.err);
        return -1;
    }
    o->sv = tf_solver_create(&o->s->problem, NULL, &o->ctx);
    o->u = malloc(3 * o->s->problem.cloud.n * sizeof *o->u);
    if (o->sv == NULL) {
        fprintf(stderr, "homogeneous: %s\n", o->ctx.err);
        return -1;
    }
    return 0;
}

static void close_cube(opened *o)
{
    free(o->u);
    tf_solver_destroy(o->sv);
    tf_scene_free(o->s);
}

static int stretch_study(void)
{
    const char *mats[][2] = {{"svk", "{law: svk, E: 1.0, nu: 0.3}"},
                             {"neo-hookean", "{law: neo-hookean, E: 1.0, nu: 0.3}"},
                             {"neo-hookean", "{law: neo-hookean, E: 1.0, nu: 0.45}"}};
    const double ends[2] = {0.5, 2.0};
    printf("method,law,nu,stretch,force_N,closed_form_N,force_error,field_error\n");
    for (int m = 0; m < 2; ++m) {
        for (int l = 0; l < 3; ++l) {
            for (int e = 0; e < 2; ++e) {
                opened o;
                if (open_cube(&o, methods[m], mats[l][1], 1, ends[e], 0) != 0) {
                    return 1;
                }
                const tf_material *mat = &o.s->problem.material;
                for (int k = 1; k <= 10; ++k) {
                    double sc = k / 10.0, lam = 1 + sc * (ends[e] - 1), lat, p, f[3];
                    if (tf_nonlinear_advance(o.sv, sc, -1, NULL, 0) != 0 ||
                        tf_nonlinear_region_force(o.sv, HOMOG_XPLUS, f) != 0 ||
                        tf_nonlinear_displacements(o.sv, o.u) != 0 ||
                        homog_uniaxial(mat, lam, &lat, &p) != 0) {
                        fprintf(stderr, "homogeneous: %s %s stretch %g: %s\n", methods[m],
                                mats[l][0], lam, o.ctx.err);
                        printf("%s,%s,%g,%.4f,failed,,,\n", methods[m], mats[l][0],
                               tf_material_get(mat, "nu"),
                               lam);
                        break;
                    }
                    double fc = p * HOMOG_L * HOMOG_L;
                    printf("%s,%s,%g,%.4f,%.12g,%.12g,%.3e,%.3e\n", methods[m], mats[l][0],
                           tf_material_get(mat, "nu"), lam, f[0], fc, fabs(f[0] - fc) / fabs(fc),
                           homog_field_error(&o.s->problem, o.u, lam, lat));
                }
                fprintf(stderr, "homogeneous: %s %s nu %g to %g done\n", methods[m], mats[l][0],
                        tf_material_get(mat, "nu"), ends[e]);
                close_cube(&o);
            }
        }
    }
    return 0;
}

/* The seed's N(eps) = eps + k eps^2 and its inverse. */
static double adjust(double k, double e) { return e + k * e * e; }
static double unadjust(double k, double n) { return k == 0 ? n : (-1 + sqrt(1 + 4 * k * n)) / (2 * k); }

static int relax_study(void)
{
    const char *mats[][2] = {
        {"kelvin k=0", "{law: kelvin, nu: 0.3, k1: 0.2, k2: 0.12, eta: 0.3}"},
        {"kelvin k=5", "{law: kelvin, nu: 0.3, k1: 0.2, k2: 0.12, eta: 0.3, k: 5}"},
        {"kelvin-neo-hookean", "{law: kelvin-neo-hookean, nu: 0.3, k1: 0.2, k2: 0.12, eta: 0.3}"}};
    const double strain = 0.05, dt = 0.25;
    printf("method,law,time_s,force_N,closed_form_N,force_error,field_error\n");
    for (int m = 0; m < 2; ++m) {
        for (int l = 0; l < 3; ++l) {
            opened o;
            if (open_cube(&o, methods[m], mats[l][1], 1, 1 + strain, 0) != 0) {
                return 1;
            }
            const tf_material *mat = &o.s->problem.material;
            double g_inf, tau, lat, p0;
            tf_material_relaxation(mat, &g_inf, &tau);
            if (homog_uniaxial(mat, 1 + strain, &lat, &p0) != 0) {
                return 1;
            }
            for (int k = 0; k <= 40; ++k) { /* the step at t = 0, then hold to 10 s */
                double t = k * dt, f[3];
                if (tf_nonlinear_advance(o.sv, 1, -1, NULL, k == 0 ? 0 : dt) != 0 ||
                    tf_nonlinear_region_force(o.sv, HOMOG_XPLUS, f) != 0 ||
                    tf_nonlinear_displacements(o.sv, o.u) != 0) {
                    fprintf(stderr, "homogeneous: %s: %s\n", mats[l][0], o.ctx.err);
                    return 1;
                }
                /* sigma(t) = E(t) N(eps0) (seed); S(t) = g(t) S0 (neo-Hookean variant) */
                double g = g_inf + (1 - g_inf) * exp(-t / tau);
                double fc = g * p0 * HOMOG_L * HOMOG_L;
                printf("%s,%s,%g,%.12g,%.12g,%.3e,%.3e\n", methods[m], mats[l][0], t, f[0], fc,
                       fabs(f[0] - fc) / fabs(fc),
                       homog_field_error(&o.s->problem, o.u, 1 + strain, lat));
            }
            close_cube(&o);
            fprintf(stderr, "homogeneous: relaxation %s %s done\n", methods[m], mats[l][0]);
        }
    }
    (void)adjust;
    return 0;
}

/* Creep: a stress step sigma0 held to 5 s; N(eps(t)) = sigma0 J(t). */
static int creep_study(void)
{
    const char *mats[][2] = {
        {"kelvin k=0", "{law: kelvin, nu: 0.3, k1: 0.2, k2: 0.12, eta: 0.3}"},
        {"kelvin k=5", "{law: kelvin, nu: 0.3, k1: 0.2, k2: 0.12, eta: 0.3, k: 5}"}};
    const double sigma0 = 0.01, tend = 5;
    printf("method,law,dt_s,strain_at_5s,closed_form,error,order\n");
    for (int m = 0; m < 2; ++m) {
        for (int l = 0; l < 2; ++l) {
            double prev = NAN;
            for (int j = 0; j <= 6; ++j) {
                double dt = ldexp(1.0, -j);
                opened o;
                if (open_cube(&o, methods[m], mats[l][1], 0, 1, sigma0 * HOMOG_L * HOMOG_L) != 0) {
                    return 1;
                }
                const tf_material *mat = &o.s->problem.material;
                int steps = (int)lround(tend / dt);
                for (int k = 0; k <= steps; ++k) {
                    if (tf_nonlinear_advance(o.sv, 1, -1, NULL, k == 0 ? 0 : dt) != 0) {
                        fprintf(stderr, "homogeneous: %s: %s\n", mats[l][0], o.ctx.err);
                        return 1;
                    }
                }
                tf_nonlinear_displacements(o.sv, o.u);
                /* the mean axial strain of the x+ face's nodes */
                double sum = 0;
                size_t cnt = 0;
                for (size_t i = 0; i < o.s->problem.cloud.n; ++i) {
                    if (fabs(o.s->problem.cloud.xyz[3 * i] - HOMOG_L) < 1e-9) {
                        sum += o.u[3 * i] / HOMOG_L;
                        cnt++;
                    }
                }
                double k1 = tf_material_get(mat, "k1"), k2 = tf_material_get(mat, "k2");
                double tc = tf_material_get(mat, "eta") * (k1 + k2) / (k1 * k2);
                double jt = 1 / k1 - k2 / (k1 * (k1 + k2)) * exp(-tend / tc);
                double exact = unadjust(tf_material_get(mat, "k"), sigma0 * jt);
                double eps = sum / (double)cnt;
                double err = fabs(eps - exact) / fabs(exact);
                printf("%s,%s,%g,%.12g,%.12g,%.3e,", methods[m], mats[l][0], dt, eps, exact, err);
                if (isfinite(prev)) {
                    printf("%.2f", log2(prev / err));
                }
                printf("\n");
                fflush(stdout);
                prev = err;
                close_cube(&o);
            }
            fprintf(stderr, "homogeneous: creep %s %s done\n", methods[m], mats[l][0]);
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "stretch") == 0) {
        return stretch_study();
    }
    if (argc == 2 && strcmp(argv[1], "relax") == 0) {
        return relax_study();
    }
    if (argc == 2 && strcmp(argv[1], "creep") == 0) {
        return creep_study();
    }
    fprintf(stderr, "usage: homogeneous stretch|relax|creep\n");
    return 2;
}
