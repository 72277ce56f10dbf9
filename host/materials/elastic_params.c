/*
 * elastic_params.c — the parameters the isotropic elastic laws share,
 * Young's modulus and Poisson's ratio (laws.h), their checks, and the
 * message every law's check writes.
 */
#include <math.h>
#include <stdio.h>

#include "materials/laws.h"

const tf_law_param tf_elastic_params[TF_ELASTIC_PARAMS] = {
    [TF_ELASTIC_E] = {"E", "Young's modulus, MPa", NAN},
    [TF_ELASTIC_NU] = {"nu", "Poisson's ratio", NAN},
};

const char *tf_law_bad(char *msg, size_t len, const char *key, double v, const char *why)
{
    snprintf(msg, len, "%s (got %g)", why, v);
    return key;
}

void tf_elastic_moduli(const double *p, double *young, double *poisson)
{
    *young = p[TF_ELASTIC_E];
    *poisson = p[TF_ELASTIC_NU];
}

const char *tf_poisson_check(double nu, char *msg, size_t len)
{
    if (!isfinite(nu) || !(nu > -1 && nu < 0.5)) {
        return tf_law_bad(msg, len, "nu", nu,
                          "Poisson's ratio must lie in (-1, 0.5); 0.5 is incompressible, which "
                          "this displacement formulation cannot represent");
    }
    return NULL;
}

const char *tf_elastic_check(const double *p, char *msg, size_t len)
{
    double e = p[TF_ELASTIC_E];
    if (!isfinite(e) || !(e > 0)) {
        return tf_law_bad(msg, len, "E", e, "Young's modulus must be a finite number > 0 MPa");
    }
    return tf_poisson_check(p[TF_ELASTIC_NU], msg, len);
}
