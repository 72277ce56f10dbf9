/*
 * hertz.c — the Hertz test of seed 004 §3 (GUIDE §5 "hertz") for the MLS
 * collocation solver: a rigid sphere pressed into a block, the force at
 * each indentation against F = 4/3 E* sqrt(R) d^(3/2) (eq 13),
 * 1/E* = (1 - nu^2)/E (eq 14, rigid indenter).
 *
 * The block is a quarter of [-L, L]^2 x [-L, 0] with mirror planes x = 0,
 * y = 0, bottom and sides clamped, particles on nested grids
 * (hertz_cloud.h).  Each indentation is a static answer (dynamic
 * relaxation) continued from the previous one.  Besides F/F_theory, the
 * indentation error is given as seed 004 measures it, at the force: the
 * theory's indentation for the computed force, d_th(F) = (3F / (4 E*
 * sqrt R))^(2/3), against the imposed d.  The L2 errors over the
 * indentations are the relative 2-norms of F - F_th and d - d_th(F) (seed
 * 004 Figs 3-5).
 *
 *   hertz [--cells C] [--levels N] [--ratio Q] [--core L0] [--radius R] [--young E]
 *         [--nu NU] [--law svk|linear|neohooke] [--indent d1,d2,..] [--stab S] [--neighbours K]
 *         [--support S] [--volumes grid|seed] [--tol T] [--csv FILE]
 *         [--label TEXT] [--check MAXERR]
 *
 * --indent takes d/R.  --check fails (exit 1) when any indentation error
 * |d / d_th(F) - 1| exceeds MAXERR.  Bad arguments exit 2.  --csv appends
 * one row per indentation: label, law, stab, neighbours, support,
 * particles, images, cells, levels, h0, L, R, nu, d, a, F, F_th, d_th,
 * d/d_th - 1, contacts, steps, seconds.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hertz_cloud.h"
#include "solvers/collocation/colloc.h"

typedef struct args {
    int cells, levels, seed_volumes;
    tf_law law;
    double core, radius, young, nu, stab, support, tol, check, ratio;
    unsigned neighbours;
    double indent[16];
    size_t n_indent;
    const char *csv, *label;
} args;

static int usage(const char *msg, const char *what)
{
    fprintf(stderr, "hertz: %s%s\n(see the comment at the top of tests/colloc/hertz.c)\n", msg,
            what ? what : "");
    return 2;
}

static int number(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return end != s && *end == '\0' && isfinite(*v) ? 0 : -1;
}

static int parse(int argc, char **argv, args *a)
{
    *a = (args){.law = TF_LAW_SVK, .ratio = 2, .cells = 8, .levels = 7, .core = 5, .radius = 20, .young = 1, .nu = 0.3,
                .stab = -1, .support = -1, .tol = 1e-6, .check = -1, .label = ""};
    const double def[4] = {0.0025, 0.005, 0.0075, 0.01};
    for (size_t k = 0; k < 4; ++k) {
        a->indent[a->n_indent++] = def[k];
    }
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        double x;
        if (v == NULL) {
            return usage("missing value after ", o);
        }
        ++i;
        if (!strcmp(o, "--csv")) {
            a->csv = v;
        } else if (!strcmp(o, "--label")) {
            a->label = v;
        } else if (!strcmp(o, "--volumes")) {
            if (strcmp(v, "grid") && strcmp(v, "seed")) {
                return usage("--volumes takes grid or seed, not ", v);
            }
            a->seed_volumes = !strcmp(v, "seed");
        } else if (!strcmp(o, "--law")) {
            if (!strcmp(v, "svk")) {
                a->law = TF_LAW_SVK;
            } else if (!strcmp(v, "linear")) {
                a->law = TF_LAW_LINEAR;
            } else if (!strcmp(v, "neohooke")) {
                a->law = TF_LAW_NEOHOOKE;
            } else {
                return usage("--law takes svk, linear or neohooke, not ", v);
            }
        } else if (!strcmp(o, "--indent")) {
            a->n_indent = 0;
            char buf[256], *save = NULL;
            snprintf(buf, sizeof buf, "%s", v);
            for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
                if (a->n_indent == 16 || number(t, &x) || !(x > 0 && x < 0.5)) {
                    return usage("--indent takes up to 16 values of d/R in (0, 0.5): ", v);
                }
                a->indent[a->n_indent++] = x;
            }
        } else if (number(v, &x)) {
            return usage("not a number: ", v);
        } else if (!strcmp(o, "--cells")) {
            a->cells = (int)x;
        } else if (!strcmp(o, "--levels")) {
            a->levels = (int)x;
        } else if (!strcmp(o, "--ratio")) {
            a->ratio = x;
        } else if (!strcmp(o, "--core")) {
            a->core = x;
        } else if (!strcmp(o, "--radius")) {
            a->radius = x;
        } else if (!strcmp(o, "--young")) {
            a->young = x;
        } else if (!strcmp(o, "--nu")) {
            a->nu = x;
        } else if (!strcmp(o, "--stab")) {
            a->stab = x;
        } else if (!strcmp(o, "--neighbours")) {
            a->neighbours = (unsigned)x;
        } else if (!strcmp(o, "--support")) {
            a->support = x;
        } else if (!strcmp(o, "--tol")) {
            a->tol = x;
        } else if (!strcmp(o, "--check")) {
            a->check = x;
        } else {
            return usage("unknown option ", o);
        }
    }
    if (a->cells < 2 || a->levels < 1 || a->levels > 40 || !(a->core > 0) ||
        !(a->radius > 0) || !(a->ratio >= 1.2 && a->ratio <= 4)) {
        return usage("--cells must be >= 2, --levels 1..40, --ratio 1.2..4, --core and --radius "
                     "> 0", NULL);
    }
    return 0;
}

/* One row per indentation: printed, and appended to the CSV. */
typedef struct row {
    double d, a, F, Fth, dth;
    size_t steps, contacts;
    double seconds;
} row;

static void report(const args *a, const hertz_cloud *hc, size_t ghosts, const row *r, size_t m,
                   FILE *csv)
{
    double h0 = a->core / a->cells, sF = 0, sF0 = 0, sd = 0, sd0 = 0, worst = 0;
    printf("%6s %8s %7s %8s %10s %10s %8s %8s %7s %6s\n", "d/R", "a/h0", "a/L", "contacts",
           "F (N)", "F_theory", "F/F_th", "d/d_th", "steps", "s");
    for (size_t k = 0; k < m; ++k) {
        const row *x = r + k;
        printf("%6.4f %8.3f %7.4f %8zu %10.5g %10.5g %8.4f %8.4f %7zu %6.2f\n", x->d / a->radius,
               x->a / h0, x->a / hc->L, x->contacts, x->F, x->Fth, x->F / x->Fth, x->d / x->dth,
               x->steps, x->seconds);
        sF += (x->F - x->Fth) * (x->F - x->Fth);
        sF0 += x->Fth * x->Fth;
        sd += (x->d - x->dth) * (x->d - x->dth);
        sd0 += x->dth * x->dth;
        worst = fmax(worst, fabs(x->d / x->dth - 1));
        if (csv) {
            fprintf(csv,
                    "%s,%s,%g,%u,%g,%zu,%zu,%d,%d,%g,%g,%g,%g,%g,%g,%.17g,%.17g,%.17g,%.6g,%zu,"
                    "%zu,%.3f\n",
                    a->label, tf_law_name(a->law), a->stab, a->neighbours, a->support, hc->n,
                    ghosts, a->cells, a->levels, h0, hc->L, a->radius, a->nu, x->d, x->a, x->F,
                    x->Fth, x->dth, x->d / x->dth - 1, x->contacts, x->steps, x->seconds);
        }
    }
    printf("L2 error: force %.4f, indentation %.4f; largest indentation error %.4f\n",
           sqrt(sF / sF0), sqrt(sd / sd0), worst);
}

int main(int argc, char **argv)
{
    args a;
    if (parse(argc, argv, &a) != 0) {
        return 2;
    }
    hertz_cloud hc;
    double h0 = a.core / a.cells;
    if (hertz_cloud_make(&hc, h0, a.cells, a.levels, a.ratio) != 0) {
        fprintf(stderr, "hertz: out of memory for the cloud\n");
        return 1;
    }
    const tf_colloc_mirror mirrors[2] = {{0, 0}, {1, 0}};
    tf_colloc_body body = {.n = hc.n, .X = hc.X, .fixed = hc.fixed,
                           .volume = a.seed_volumes ? NULL : hc.volume,
                           .total_volume = hc.volume_total,
                           .material = {.law = a.law, .young = a.young, .poisson = a.nu},
                           .density = 1e-9, .mirrors = mirrors, .n_mirrors = 2};
    tf_colloc_opts o;
    tf_colloc_defaults(&o);
    o.stab = a.stab >= 0 ? a.stab : o.stab;
    o.support = a.support > 0 ? a.support : o.support;
    o.neighbours = a.neighbours ? a.neighbours : o.neighbours;
    a.stab = o.stab; /* as used, for the CSV */
    a.support = o.support;
    a.neighbours = o.neighbours;
    char err[512];
    double t0 = omp_get_wtime();
    tf_colloc *c = tf_colloc_new(&body, &o, err, sizeof err);
    if (c == NULL) {
        fprintf(stderr, "hertz: %s\n", err);
        hertz_cloud_free(&hc);
        return 2;
    }
    printf("== Hertz: %zu particles (%zu mirror images), quarter block L = %g mm, h0 = %g mm, "
           "R = %g mm, %s E = %g MPa, nu = %g, %u neighbours, support %g, stab %g, %s volumes "
           "(set-up %.2f s) ==\n",
           hc.n, tf_colloc_ghosts(c), hc.L, h0, a.radius, tf_law_name(a.law), a.young, a.nu, o.neighbours, o.support,
           o.stab, a.seed_volumes ? "eqs 2-3" : "Voronoi", omp_get_wtime() - t0);
    tf_colloc_sphere s = {.centre = {0, 0, a.radius}, .dir = {0, 0, -1}, .radius = a.radius,
                          .drive = TF_COLLOC_INDENT};
    tf_colloc_set_sphere(c, &s, err, sizeof err);
    double estar = a.young / (1 - a.nu * a.nu), sr = sqrt(a.radius);
    row r[16];
    int rc = 0;
    for (size_t k = 0; k < a.n_indent && rc == 0; ++k) {
        double d = a.indent[k] * a.radius;
        tf_colloc_set_travel(c, d);
        tf_colloc_relax_opts ro;
        tf_colloc_relax_defaults(&ro);
        ro.tol = a.tol;
        tf_colloc_relax_stats st;
        double t1 = omp_get_wtime();
        int q = tf_colloc_relax(c, &ro, &st, err, sizeof err);
        if (q != 0) {
            fprintf(stderr, "hertz: d/R = %g: %s\n", a.indent[k],
                    q < 0 ? err : "the relaxation did not converge");
            rc = 1;
            break;
        }
        double F = 4 * tf_colloc_contact_force(c); /* the quarter's, times 4 */
        r[k] = (row){.d = d, .a = sqrt(a.radius * d), .F = F,
                     .Fth = 4.0 / 3 * estar * sr * pow(d, 1.5),
                     .dth = pow(3 * F / (4 * estar * sr), 2.0 / 3), .steps = st.steps,
                     .contacts = tf_colloc_contacts(c), .seconds = omp_get_wtime() - t1};
    }
    FILE *csv = NULL;
    if (rc == 0 && a.csv) {
        csv = fopen(a.csv, "a");
        if (csv == NULL) {
            fprintf(stderr, "hertz: cannot append to %s\n", a.csv);
            rc = 1;
        }
    }
    if (rc == 0) {
        report(&a, &hc, tf_colloc_ghosts(c), r, a.n_indent, csv);
        for (size_t k = 0; k < a.n_indent && a.check >= 0; ++k) {
            if (!(fabs(r[k].d / r[k].dth - 1) <= a.check)) {
                printf("FAIL: indentation error %.4f at d/R = %g exceeds %g\n",
                       r[k].d / r[k].dth - 1, a.indent[k], a.check);
                rc = 1;
            }
        }
        if (a.check >= 0 && rc == 0) {
            printf("every indentation within %g of Hertz's: ok\n", a.check);
        }
    }
    if (csv && fclose(csv) != 0) {
        rc = 1;
    }
    tf_colloc_free(c);
    hertz_cloud_free(&hc);
    return rc;
}
