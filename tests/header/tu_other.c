/*
 * tu_other.c — the second translation unit of the two-TU header test.
 */
#include "families.h"

uint32_t other_n_out(void);

uint32_t other_n_out(void)
{
    return tfit_nodal_a.n_out;
}
