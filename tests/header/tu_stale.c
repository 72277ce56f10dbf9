/*
 * tu_stale.c — a file compiled against another version of families.h than
 * the one whose IMPLEMENTATION is linked (a regenerated header, N_OUT
 * different): its buffer is sized by the stale TFIT_NODAL_A_N_OUT.  The
 * header names the model object after its CRC (header-format.md §2), so
 * this file refers to a symbol the linked header does not define and the
 * link fails: check-header requires that, naming the symbol.
 */
#include "families.h"

uint32_t other_n_out(void);

uint32_t other_n_out(void)
{
    static float u[3 * TFIT_NODAL_A_N_OUT];
    const float f[3] = {0.0f, 0.0f, 0.0f};
    return tfit_displacements(&tfit_nodal_a, f, u) == TFIT_OK ? tfit_nodal_a.n_out : 0u;
}
