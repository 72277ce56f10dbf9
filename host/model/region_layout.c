/*
 * region_layout.c — see region_layout.h.
 */
#include "model/region_layout.h"

/* T(p) = (p+1)(p+2)(p+3)/6 terms of total degree <= p (model.h's
 * tf_terms; not included: model.c includes this file's header) */
static uint32_t terms(uint32_t p)
{
    return (p + 1) * (p + 2) * (p + 3) / 6;
}

uint32_t tf_region_law_terms(uint32_t degree)
{
    return terms(degree) - 4;
}

uint32_t tf_region_surface_terms(uint32_t degree)
{
    return terms(degree) - 1;
}

uint32_t tf_region_law_stride(const uint32_t *dims)
{
    return 1 + tf_region_law_terms(dims[2]);
}

uint32_t tf_region_surface_stride(const uint32_t *dims)
{
    return dims[2] * tf_region_surface_terms(dims[3]) + 3 * dims[2] * dims[4];
}

uint32_t tf_region_control_points(const uint32_t *dims)
{
    return (dims[0] + 2) * (dims[1] + 2);
}

/* The grid both forms share: 2 .. TFIT_REGION_MAX_GRID sites per side. */
static int grid_ok(uint32_t n_out, const uint32_t *dims)
{
    return n_out != 0 && n_out <= (1u << 20) && dims[0] >= 2 && dims[1] >= 2 &&
           dims[0] <= TFIT_REGION_MAX_GRID && dims[1] <= TFIT_REGION_MAX_GRID;
}

uint32_t tf_region_law_ncoef(uint32_t n_out, const uint32_t *dims)
{
    if (!grid_ok(n_out, dims) || n_out != 1 || dims[2] < 2 || dims[2] > TFIT_REGION_MAX_DEGREE) {
        return 0;
    }
    return TF_REGION_LAW_CTRL + tf_region_control_points(dims) * tf_region_law_stride(dims);
}

uint32_t tf_region_surface_near_at(const uint32_t *dims)
{
    return TF_REGION_SURFACE_CTRL + tf_region_control_points(dims) * tf_region_surface_stride(dims);
}

uint32_t tf_region_surface_ncoef(uint32_t n_out, const uint32_t *dims)
{
    if (!grid_ok(n_out, dims) || dims[2] == 0 || dims[2] > TFIT_REGION_MAX_RANK || dims[3] == 0 ||
        dims[3] > TFIT_REGION_SURFACE_MAX_DEGREE || dims[4] > 1 ||
        dims[5] > TFIT_REGION_MAX_NEAR || (dims[5] != 0 && dims[3] != 1)) {
        return 0;
    }
    const uint64_t n = (uint64_t)tf_region_control_points(dims) *
                           (tf_region_surface_stride(dims) + TF_REGION_NEAR_FLOATS * dims[5]) +
                       3ull * n_out * dims[2] + TF_REGION_SURFACE_CTRL;
    return n > UINT32_MAX ? 0 : (uint32_t)n;
}
