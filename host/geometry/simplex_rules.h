/*
 * simplex_rules.h — symmetric Gauss rules on tetrahedra (the integration
 * cells of an organ's node cloud, tetmesh.h) and on triangles (surface
 * tractions), with positive weights and every point inside:
 *
 *   tetrahedron  degree 1:  1 point  (centroid)
 *                degree 2:  4 points (Stroud T3:2-1; Keast 1986)
 *                degree 5: 15 points (Stroud T3:5-1; Keast 1986)
 *   triangle     degree 1:  1 point  (centroid)
 *                degree 2:  3 points (Stroud T2:2-1; Strang and Fix 1973)
 *                degree 5:  7 points (Radon 1948; Stroud T2:5-1)
 *
 * A request for degree d gets the smallest of these of degree >= d (3 and 4
 * give the degree-5 rules).  "Degree d" means: every polynomial of total
 * degree <= d is integrated exactly (test_geometry_rules.c checks every
 * monomial, and that degree d + 1 is not).
 */
#ifndef TF_SIMPLEX_RULES_H
#define TF_SIMPLEX_RULES_H

#define TF_SIMPLEX_MAX_POINTS 15
#define TF_SIMPLEX_MAX_DEGREE 5

typedef struct tf_simplex_rule {
    unsigned degree;                             /* exact up to this total degree */
    unsigned n;                                  /* points */
    double bary[TF_SIMPLEX_MAX_POINTS][4];       /* barycentric coordinates (3 used on triangles) */
    double w[TF_SIMPLEX_MAX_POINTS];             /* fractions of the measure, summing to 1 */
} tf_simplex_rule;

/* Fill r with the rule for `degree`.  Return 0, or -1 for degree 0 or
 * above TF_SIMPLEX_MAX_DEGREE. */
int tf_tet_rule(unsigned degree, tf_simplex_rule *r);
int tf_tri_rule(unsigned degree, tf_simplex_rule *r);

/* The points and weights (mm^3) of r on the tetrahedron with corners c;
 * weights use |volume|. */
void tf_tet_points(const tf_simplex_rule *r, const double c[4][3], double (*x)[3], double *w);

/* The points and weights (mm^2, area) of r on the triangle with corners c. */
void tf_tri_points(const tf_simplex_rule *r, const double c[3][3], double (*x)[3], double *w);

#endif /* TF_SIMPLEX_RULES_H */
