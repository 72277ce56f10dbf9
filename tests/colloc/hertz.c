/*
 * hertz.c — the Hertz test of the collocation solver (verify/hertz.h) with
 * every option, for the study (make hertz-study) and the check
 * (make check-colloc); `tissuefit verify hertz` runs the same test with
 * the defaults.
 *
 *   hertz [--cells C] [--levels N] [--ratio Q] [--core L0] [--radius R]
 *         [--young E] [--nu NU] [--law NAME] [--indent d1,d2,..]
 *         [--stab S] [--neighbours K] [--support S] [--volumes grid|seed]
 *         [--tol T] [--csv FILE] [--label TEXT] [--check MAXERR]
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

#include "base/context.h"
#include "verify/hertz.h"

typedef struct args {
    tf_hertz_opts h;
    double check;
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
    *a = (args){.check = -1, .label = ""};
    tf_hertz_opts *h = &a->h;
    tf_hertz_defaults(h);
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
            h->seed_volumes = !strcmp(v, "seed");
        } else if (!strcmp(o, "--law")) {
            h->law = tf_law_find(v); /* (one without E and nu: tf_hertz_run refuses it) */
            if (h->law == NULL) {
                return usage("--law takes a registered law (svk, linear, neo-hookean), not ", v);
            }
        } else if (!strcmp(o, "--indent")) {
            h->n_indent = 0;
            char buf[256], *save = NULL;
            snprintf(buf, sizeof buf, "%s", v);
            for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
                if (h->n_indent == TF_HERTZ_MAX_INDENT || number(t, &x)) {
                    return usage("--indent takes up to 16 values of d/R: ", v);
                }
                h->indent[h->n_indent++] = x;
            }
        } else if (number(v, &x)) {
            return usage("not a number: ", v);
        } else if (!strcmp(o, "--cells")) {
            h->cells = (int)x;
        } else if (!strcmp(o, "--levels")) {
            h->levels = (int)x;
        } else if (!strcmp(o, "--ratio")) {
            h->ratio = x;
        } else if (!strcmp(o, "--core")) {
            h->core = x;
        } else if (!strcmp(o, "--radius")) {
            h->radius = x;
        } else if (!strcmp(o, "--young")) {
            h->young = x;
        } else if (!strcmp(o, "--nu")) {
            h->nu = x;
        } else if (!strcmp(o, "--stab")) {
            h->colloc.stab = x;
        } else if (!strcmp(o, "--neighbours")) {
            h->colloc.neighbours = (unsigned)x;
        } else if (!strcmp(o, "--support")) {
            h->colloc.support = x;
        } else if (!strcmp(o, "--tol")) {
            h->tol = x;
        } else if (!strcmp(o, "--check")) {
            a->check = x;
        } else {
            return usage("unknown option ", o);
        }
    }
    return 0;
}

/* The table, the L2 errors, and the CSV rows. */
static void report(const args *a, const tf_hertz_row *r, FILE *csv)
{
    const tf_hertz_opts *h = &a->h;
    printf("%6s %8s %7s %8s %10s %10s %8s %8s %7s %6s\n", "d/R", "a/h0", "a/L", "contacts",
           "F (N)", "F_theory", "F/F_th", "d/d_th", "steps", "s");
    for (size_t k = 0; k < h->n_indent; ++k) {
        const tf_hertz_row *x = r + k;
        printf("%6.4f %8.3f %7.4f %8zu %10.5g %10.5g %8.4f %8.4f %7zu %6.2f\n", x->d / h->radius,
               x->a / x->h0, x->a / x->L, x->contacts, x->F, x->F_theory, x->F / x->F_theory,
               x->d / x->d_theory, x->steps, x->seconds);
        if (csv) {
            fprintf(csv,
                    "%s,%s,%g,%u,%g,%zu,%zu,%d,%d,%g,%g,%g,%g,%g,%g,%.17g,%.17g,%.17g,%.6g,%zu,"
                    "%zu,%.3f\n",
                    a->label, h->law->name, h->colloc.stab, h->colloc.neighbours,
                    h->colloc.support, x->particles, x->images, h->cells, h->levels, x->h0, x->L,
                    h->radius, h->nu, x->d, x->a, x->F, x->F_theory, x->d_theory,
                    x->d / x->d_theory - 1, x->contacts, x->steps, x->seconds);
        }
    }
    double l2F, l2d, worst;
    tf_hertz_errors(r, h->n_indent, &l2F, &l2d, &worst);
    printf("L2 error: force %.4f, indentation %.4f; largest indentation error %.4f\n", l2F, l2d,
           worst);
}

int main(int argc, char **argv)
{
    args a;
    if (parse(argc, argv, &a) != 0) {
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    tf_hertz_row r[TF_HERTZ_MAX_INDENT];
    const tf_hertz_opts *h = &a.h;
    printf("== Hertz: cells %d, levels %d (ratio %g), core %g mm, R = %g mm, %s E = %g MPa, "
           "nu = %g, %u neighbours, support %g, stab %g, %s volumes ==\n",
           h->cells, h->levels, h->ratio, h->core, h->radius, h->law->name, h->young,
           h->nu, h->colloc.neighbours, h->colloc.support, h->colloc.stab,
           h->seed_volumes ? "eqs 2-3" : "Voronoi");
    if (tf_hertz_run(h, r, &ctx) != 0) {
        fprintf(stderr, "%s\n", ctx.err);
        return strstr(ctx.err, "did not converge") || strstr(ctx.err, "inverted") ? 1 : 2;
    }
    printf("%zu particles (%zu mirror images), quarter block L = %g mm, h0 = %g mm\n",
           r[0].particles, r[0].images, r[0].L, r[0].h0);
    FILE *csv = NULL;
    if (a.csv && (csv = fopen(a.csv, "a")) == NULL) {
        fprintf(stderr, "hertz: cannot append to %s\n", a.csv);
        return 1;
    }
    report(&a, r, csv);
    int rc = csv && fclose(csv) != 0;
    for (size_t k = 0; k < h->n_indent && a.check >= 0; ++k) {
        if (!(fabs(r[k].d / r[k].d_theory - 1) <= a.check)) {
            printf("FAIL: indentation error %.4f at d/R = %g exceeds %g\n",
                   r[k].d / r[k].d_theory - 1, h->indent[k], a.check);
            rc = 1;
        }
    }
    if (a.check >= 0 && rc == 0) {
        printf("ok: every indentation within %g of Hertz's theory\n", a.check);
    }
    return rc;
}
