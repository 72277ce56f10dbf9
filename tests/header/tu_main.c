/*
 * tu_main.c — with tu_other.c, proves that a generated header included from
 * two translation units defines its tables once: this file defines the
 * implementation, tu_other.c only sees extern declarations.
 */
#include <stdio.h>

#define TFIT_FAMILIES_IMPLEMENTATION
#include "families.h"

uint32_t other_n_out(void);

int main(void)
{
    /* Same object seen from both translation units. */
    if (other_n_out() != tfit_nodal_a.n_out || tfit_model_check(&tfit_nodal_a) != TFIT_OK) {
        fprintf(stderr, "two translation units disagree about tfit_nodal_a\n");
        return 1;
    }
    printf("two-TU link: ok (n_out %u)\n", (unsigned)other_n_out());
    return 0;
}
