/*
 * vec3.h — the few 3-vector operations the geometry layer repeats.
 */
#ifndef TF_VEC3_H
#define TF_VEC3_H

#include <math.h>

static inline void tf_v3_sub(const double a[3], const double b[3], double d[3])
{
    d[0] = a[0] - b[0];
    d[1] = a[1] - b[1];
    d[2] = a[2] - b[2];
}

static inline double tf_v3_dot(const double u[3], const double v[3])
{
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

static inline void tf_v3_cross(const double u[3], const double v[3], double c[3])
{
    c[0] = u[1] * v[2] - u[2] * v[1];
    c[1] = u[2] * v[0] - u[0] * v[2];
    c[2] = u[0] * v[1] - u[1] * v[0];
}

static inline double tf_v3_norm(const double v[3])
{
    return sqrt(tf_v3_dot(v, v));
}

/* det[u v w] = u . (v x w). */
static inline double tf_v3_det(const double u[3], const double v[3], const double w[3])
{
    double c[3];
    tf_v3_cross(v, w, c);
    return tf_v3_dot(u, c);
}

/* det[b - a, c - a, d - a]: six times the signed volume of tetrahedron abcd. */
static inline double tf_v3_orient(const double a[3], const double b[3], const double c[3],
                                  const double d[3])
{
    double u[3], v[3], w[3];
    tf_v3_sub(b, a, u);
    tf_v3_sub(c, a, v);
    tf_v3_sub(d, a, w);
    return tf_v3_det(u, v, w);
}

/* Area of triangle abc. */
static inline double tf_v3_area(const double a[3], const double b[3], const double c[3])
{
    double u[3], v[3], n[3];
    tf_v3_sub(b, a, u);
    tf_v3_sub(c, a, v);
    tf_v3_cross(u, v, n);
    return 0.5 * tf_v3_norm(n);
}

#endif /* TF_VEC3_H */
