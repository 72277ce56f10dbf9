/*
 * simplex_rules.c — symmetric rules on tetrahedra and triangles
 * (simplex_rules.h).  Each rule is a union of symmetry orbits of
 * barycentric points: the centroid, (a, a, a, 1 - 3a) and its 4
 * permutations, (a, a, 1/2 - a, 1/2 - a) and its 6, and on triangles
 * (a, a, 1 - 2a) and its 3.  The closed forms are Stroud's (Approximate
 * Calculation of Multiple Integrals, 1971) as tabulated by Keast (Comput.
 * Methods Appl. Mech. Eng. 55, 1986) for tetrahedra; the unit test proves
 * them by integrating every monomial.
 */
#include "geometry/simplex_rules.h"

#include <math.h>
#include <string.h>

#include "geometry/vec3.h"

static void point(tf_simplex_rule *r, double a, double b, double c, double d, double w)
{
    r->bary[r->n][0] = a;
    r->bary[r->n][1] = b;
    r->bary[r->n][2] = c;
    r->bary[r->n][3] = d;
    r->w[r->n++] = w;
}

/* (a, a, a, 1 - 3a) and its permutations. */
static void tet_s31(tf_simplex_rule *r, double a, double w)
{
    double b = 1 - 3 * a;
    point(r, b, a, a, a, w);
    point(r, a, b, a, a, w);
    point(r, a, a, b, a, w);
    point(r, a, a, a, b, w);
}

/* (a, a, b, b), b = 1/2 - a, and its permutations. */
static void tet_s22(tf_simplex_rule *r, double a, double w)
{
    double b = 0.5 - a;
    point(r, a, a, b, b, w);
    point(r, a, b, a, b, w);
    point(r, a, b, b, a, w);
    point(r, b, a, a, b, w);
    point(r, b, a, b, a, w);
    point(r, b, b, a, a, w);
}

/* (a, a, 1 - 2a) and its permutations. */
static void tri_s21(tf_simplex_rule *r, double a, double w)
{
    double b = 1 - 2 * a;
    point(r, b, a, a, 0, w);
    point(r, a, b, a, 0, w);
    point(r, a, a, b, 0, w);
}

int tf_tet_rule(unsigned degree, tf_simplex_rule *r)
{
    memset(r, 0, sizeof *r);
    if (degree == 1) {
        point(r, 0.25, 0.25, 0.25, 0.25, 1);
    } else if (degree == 2) {
        tet_s31(r, (5 - sqrt(5)) / 20, 0.25);
    } else if (degree <= TF_SIMPLEX_MAX_DEGREE && degree > 0) {
        double s = sqrt(15);
        point(r, 0.25, 0.25, 0.25, 0.25, 16.0 / 135);
        tet_s31(r, (7 - s) / 34, (2665 + 14 * s) / 37800);
        tet_s31(r, (7 + s) / 34, (2665 - 14 * s) / 37800);
        tet_s22(r, (10 - 2 * s) / 40, 10.0 / 189);
        degree = 5;
    } else {
        return -1;
    }
    r->degree = degree;
    return 0;
}

int tf_tri_rule(unsigned degree, tf_simplex_rule *r)
{
    memset(r, 0, sizeof *r);
    if (degree == 1) {
        point(r, 1.0 / 3, 1.0 / 3, 1.0 / 3, 0, 1);
    } else if (degree == 2) {
        tri_s21(r, 1.0 / 6, 1.0 / 3);
    } else if (degree <= TF_SIMPLEX_MAX_DEGREE && degree > 0) {
        double s = sqrt(15);
        point(r, 1.0 / 3, 1.0 / 3, 1.0 / 3, 0, 9.0 / 40);
        tri_s21(r, (6 - s) / 21, (155 - s) / 1200);
        tri_s21(r, (6 + s) / 21, (155 + s) / 1200);
        degree = 5;
    } else {
        return -1;
    }
    r->degree = degree;
    return 0;
}

static void map_points(const tf_simplex_rule *r, const double (*c)[3], int corners,
                       double measure, double (*x)[3], double *w)
{
    for (unsigned q = 0; q < r->n; ++q) {
        for (int a = 0; a < 3; ++a) {
            double sum = 0;
            for (int k = 0; k < corners; ++k) {
                sum += r->bary[q][k] * c[k][a];
            }
            x[q][a] = sum;
        }
        w[q] = r->w[q] * measure;
    }
}

void tf_tet_points(const tf_simplex_rule *r, const double c[4][3], double (*x)[3], double *w)
{
    map_points(r, c, 4, fabs(tf_v3_orient(c[0], c[1], c[2], c[3])) / 6, x, w);
}

void tf_tri_points(const tf_simplex_rule *r, const double c[3][3], double (*x)[3], double *w)
{
    map_points(r, c, 3, tf_v3_area(c[0], c[1], c[2]), x, w);
}
