/*
 * discretisation.c — see discretisation.h.
 */
#include "fitting/discretisation.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_CASES 16

typedef struct ref_case {
    double force[3];
    double *x, *u; /* 3 np each */
    size_t np;
    const double *solved; /* the solver's displacements at x, when known (3 np) */
} ref_case;

/* The directory part of path (with its slash), for files named in the index. */
static void dir_of(const char *path, char *dir, size_t len)
{
    const char *slash = strrchr(path, '/');
    snprintf(dir, len, "%.*s", slash ? (int)(slash - path + 1) : 0, path);
}

/* One case file: header node,x,y,z,ux,uy,uz then rows. */
static int read_points(tf_ctx *ctx, const char *path, ref_case *c)
{
    FILE *fp = fopen(path, "r");
    if (fp == NULL) {
        return tf_fail(ctx, "%s: %s", path, strerror(errno));
    }
    char line[512];
    size_t cap = 0, lineno = 1;
    int rc = 0;
    if (fgets(line, sizeof line, fp) == NULL || strncmp(line, "node,x,y,z,ux,uy,uz", 19) != 0) {
        tf_fail(ctx, "%s:1: expected the header node,x,y,z,ux,uy,uz", path);
        rc = -1;
    }
    while (rc == 0 && fgets(line, sizeof line, fp) != NULL) {
        ++lineno;
        double v[6];
        long node;
        if (sscanf(line, "%ld,%lf,%lf,%lf,%lf,%lf,%lf", &node, &v[0], &v[1], &v[2], &v[3], &v[4],
                   &v[5]) != 7 || !isfinite(v[0] + v[1] + v[2] + v[3] + v[4] + v[5])) {
            tf_fail(ctx, "%s:%zu: expected node,x,y,z,ux,uy,uz (7 finite numbers)", path, lineno);
            rc = -1;
            break;
        }
        if (c->np == cap) {
            cap = cap ? 2 * cap : 128;
            double *x = realloc(c->x, 3 * cap * sizeof *x), *u = x ? realloc(c->u, 3 * cap * sizeof *u) : NULL;
            if (x != NULL) {
                c->x = x;
            }
            if (u == NULL) {
                tf_fail(ctx, "%s: out of memory", path);
                rc = -1;
                break;
            }
            c->u = u;
        }
        memcpy(c->x + 3 * c->np, v, 3 * sizeof *v);
        memcpy(c->u + 3 * c->np, v + 3, 3 * sizeof *v);
        c->np++;
    }
    fclose(fp);
    if (rc == 0 && c->np == 0) {
        tf_fail(ctx, "%s: no points", path);
        rc = -1;
    }
    return rc;
}

/* The index: header fx,fy,fz,file then one case per line. */
static int read_index(tf_ctx *ctx, const char *index, ref_case *cases, size_t *n)
{
    FILE *fp = fopen(index, "r");
    if (fp == NULL) {
        return tf_fail(ctx, "%s: %s", index, strerror(errno));
    }
    char line[1024], dir[512], path[1024], file[512];
    dir_of(index, dir, sizeof dir);
    size_t lineno = 1;
    int rc = 0;
    if (fgets(line, sizeof line, fp) == NULL || strncmp(line, "fx,fy,fz,file", 13) != 0) {
        tf_fail(ctx, "%s:1: expected the header fx,fy,fz,file", index);
        rc = -1;
    }
    *n = 0;
    while (rc == 0 && fgets(line, sizeof line, fp) != NULL) {
        ++lineno;
        ref_case *c = &cases[*n];
        if (*n == MAX_CASES) {
            tf_fail(ctx, "%s:%zu: more than %d cases", index, lineno, MAX_CASES);
            rc = -1;
        } else if (sscanf(line, "%lf,%lf,%lf,%511[^\r\n]", &c->force[0], &c->force[1],
                          &c->force[2], file) != 4 ||
                   !isfinite(c->force[0] + c->force[1] + c->force[2])) {
            tf_fail(ctx, "%s:%zu: expected fx,fy,fz,file (forces in N)", index, lineno);
            rc = -1;
        } else {
            snprintf(path, sizeof path, "%s%s", file[0] == '/' ? "" : dir, file);
            ++*n;
            rc = read_points(ctx, path, c);
        }
    }
    fclose(fp);
    if (rc == 0 && *n == 0) {
        tf_fail(ctx, "%s: no cases", index);
        rc = -1;
    }
    return rc;
}

/* diff = solve - reference at the case's points (3 np). */
static int case_error(tf_ctx *ctx, tf_solver *s, int contact, const ref_case *c, double *diff)
{
    if (c->solved != NULL) { /* solved already: no nodal buffers, no solve */
        for (size_t i = 0; i < 3 * c->np; ++i) {
            diff[i] = c->solved[i] - c->u[i];
        }
        return 0;
    }
    const size_t dofs = 3 * tf_solver_node_count(s);
    double *u = malloc(dofs * sizeof *u), *grad = malloc(9 * c->np * sizeof *grad);
    int rc = -1;
    if (u == NULL || grad == NULL) {
        tf_fail(ctx, "out of memory for the reference comparison");
    } else if (tf_solver_solve(s, contact, (const double(*)[3])c->force, 1, NULL, u) != 0) {
        tf_fail(ctx, "the reference case (%g, %g, %g) N did not solve", c->force[0], c->force[1],
                c->force[2]);
    } else {
        rc = tf_solver_field(ctx, s, u, c->x, c->np, diff, grad);
    }
    for (size_t i = 0; rc == 0 && i < 3 * c->np; ++i) {
        diff[i] -= c->u[i];
    }
    free(u);
    free(grad);
    return rc;
}

/* Inverse of the 3x3 matrix whose columns are the cases' forces; 0 when
 * they are not independent. */
static int force_inverse(const ref_case *c, double inv[9])
{
    const double *a = c[0].force, *b = c[1].force, *d = c[2].force;
    /* rows of the inverse of [a b d] are the cross products over the determinant */
    const double r0[3] = {b[1] * d[2] - b[2] * d[1], b[2] * d[0] - b[0] * d[2], b[0] * d[1] - b[1] * d[0]};
    const double r1[3] = {d[1] * a[2] - d[2] * a[1], d[2] * a[0] - d[0] * a[2], d[0] * a[1] - d[1] * a[0]};
    const double r2[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double det = a[0] * r0[0] + a[1] * r0[1] + a[2] * r0[2];
    const double scale = fmax(fmax(hypot(hypot(a[0], a[1]), a[2]), hypot(hypot(b[0], b[1]), b[2])),
                              hypot(hypot(d[0], d[1]), d[2]));
    if (!(fabs(det) > 1e-9 * scale * scale * scale)) {
        return 0;
    }
    for (int k = 0; k < 3; ++k) {
        inv[k] = r0[k] / det;
        inv[3 + k] = r1[k] / det;
        inv[6 + k] = r2[k] / det;
    }
    return 1;
}

static int same_points(const ref_case *c, size_t n)
{
    for (size_t k = 1; k < n; ++k) {
        if (c[k].np != c[0].np || memcmp(c[k].x, c[0].x, 3 * c[0].np * sizeof *c[0].x) != 0) {
            return 0;
        }
    }
    return 1;
}

/* The envelope bound of a linear error field: row i of E = D F^-1. */
static double envelope_bound(const double *const diff[3], size_t rows, const double inv[9],
                             const tf_envelope *env)
{
    double worst = 0;
    for (size_t i = 0; i < rows; ++i) {
        double e[3];
        for (int a = 0; a < 3; ++a) {
            e[a] = diff[0][i] * inv[a] + diff[1][i] * inv[3 + a] + diff[2][i] * inv[6 + a];
        }
        const double at_centre = e[0] * env->centre[0] + e[1] * env->centre[1] + e[2] * env->centre[2];
        worst = fmax(worst, env->radius * hypot(hypot(e[0], e[1]), e[2]) + fabs(at_centre));
    }
    return worst;
}

/* The reference point nearest the contact point (its node when given by
 * number), and the relative error there. */
static void site_error(const tf_solver *s, const tf_problem *p, int contact, const ref_case *c,
                       const double *diff, tf_discretisation *out)
{
    const tf_contact *site = &p->contacts[contact];
    const double *xn = site->by_node ? tf_solver_coords(s) + 3 * (size_t)site->node : site->at;
    size_t best = 0;
    double gap = INFINITY;
    for (size_t j = 0; j < c->np; ++j) {
        const double d = hypot(hypot(c->x[3 * j] - xn[0], c->x[3 * j + 1] - xn[1]), c->x[3 * j + 2] - xn[2]);
        if (d < gap) {
            gap = d;
            best = j;
        }
    }
    const double *e = diff + 3 * best, *r = c->u + 3 * best;
    const double rel = hypot(hypot(e[0], e[1]), e[2]) / hypot(hypot(r[0], r[1]), r[2]);
    out->site_gap = fmax(out->site_gap, gap);
    out->site_rel = fmax(out->site_rel, rel);
}

static int compare(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact, ref_case *c,
                   size_t n, tf_discretisation *out)
{
    double *diff[MAX_CASES] = {0}, inv[9];
    int rc = 0;
    for (size_t k = 0; k < n && rc == 0; ++k) {
        const double *f = c[k].force, *ctr = p->envelope.centre;
        const double off = hypot(hypot(f[0] - ctr[0], f[1] - ctr[1]), f[2] - ctr[2]);
        diff[k] = malloc(3 * c[k].np * sizeof *diff[k]);
        if (diff[k] == NULL) {
            tf_fail(ctx, "out of memory for the reference comparison");
            rc = -1;
        } else if (!(tf_solver_caps_of(s) & TF_SOLVER_LINEAR) && off > p->envelope.radius * (1 + 1e-9)) {
            tf_fail(ctx, "%s: case %zu's force (%g, %g, %g) N lies outside the envelope",
                    out->source, k + 1, f[0], f[1], f[2]);
            rc = -1;
        } else {
            rc = case_error(ctx, s, contact, &c[k], diff[k]);
            out->reach = fmax(out->reach, off / p->envelope.radius);
        }
        for (size_t i = 0; rc == 0 && i < 3 * c[k].np; ++i) {
            out->max_mm = fmax(out->max_mm, fabs(diff[k][i]));
        }
        if (rc == 0) {
            site_error(s, p, contact, &c[k], diff[k], out);
            out->points = c[k].np;
        }
    }
    if (rc == 0 && (tf_solver_caps_of(s) & TF_SOLVER_LINEAR) && n == 3 && same_points(c, n) &&
        force_inverse(c, inv)) {
        out->max_mm = envelope_bound((const double *const[3]){diff[0], diff[1], diff[2]},
                                     3 * c[0].np, inv, &p->envelope);
        out->enveloped = 1;
    }
    for (size_t k = 0; k < n; ++k) {
        free(diff[k]);
    }
    return rc;
}

/* The comparison when the cases were read (rc 0), then the cases freed. */
static int compare_and_free(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                            ref_case *cases, size_t n, int rc, tf_discretisation *out)
{
    if (rc == 0) {
        rc = compare(ctx, s, p, contact, cases, n, out);
    }
    for (size_t k = 0; k < MAX_CASES; ++k) {
        free(cases[k].x);
        free(cases[k].u);
    }
    return rc;
}

int tf_discretisation_compare(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                              const double (*force)[3], size_t n, const double *x, size_t np,
                              const double *const *u, const double *const *solved,
                              tf_discretisation *out)
{
    ref_case cases[MAX_CASES] = {0};
    int rc = n <= MAX_CASES ? 0 : tf_fail(ctx, "more than %d reference cases", MAX_CASES);
    for (size_t k = 0; k < n && rc == 0; ++k) {
        memcpy(cases[k].force, force[k], sizeof cases[k].force);
        cases[k].np = np;
        cases[k].x = malloc(3 * np * sizeof *x);
        cases[k].u = malloc(3 * np * sizeof *x);
        if (cases[k].x == NULL || cases[k].u == NULL) {
            rc = tf_fail(ctx, "out of memory for the reference comparison");
        } else {
            memcpy(cases[k].x, x, 3 * np * sizeof *x);
            memcpy(cases[k].u, u[k], 3 * np * sizeof *x);
            cases[k].solved = solved != NULL ? solved[k] : NULL;
        }
    }
    return compare_and_free(ctx, s, p, contact, cases, n, rc, out);
}

int tf_discretisation_measure(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                              const char *index, tf_discretisation *out)
{
    memset(out, 0, sizeof *out);
    snprintf(out->source, sizeof out->source, "%s", index);
    if (contact < 0 || (size_t)contact >= p->n_contacts) {
        return tf_fail(ctx, "%s: a discretisation reference needs a contact site", index);
    }
    ref_case cases[MAX_CASES] = {0};
    size_t n = 0;
    int rc = read_index(ctx, index, cases, &n);
    out->cases = n;
    return compare_and_free(ctx, s, p, contact, cases, n, rc, out);
}
