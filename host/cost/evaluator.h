/*
 * evaluator.h — the blocks of the compiled evaluator that several forms run
 * (cycles.h): the entry of tfit_displacements and evaluate() in tfit_eval.c,
 * the projection (tfit_input.c), the basis (tfit_basis.c), the nodal and
 * modal evaluators (tfit_nodal.c, tfit_modal.c with the rows of
 * tfit_modal_armv7em.c) and the degree-1 assembly (tfit_degree1_armv7em.c),
 * each added to a mix by the numbers its loops depend on.  A form adds
 * these and its own blocks (model/forms/).
 */
#ifndef TF_EVALUATOR_H
#define TF_EVALUATOR_H

#include <stddef.h>
#include <stdint.h>

#include "cost/cycles.h"

/* tfit_input_map(): the projection, straight-line code. */
void tf_insn_input(tf_insn_mix *t, tf_core core);

/* tfit_displacements up to its call of evaluate() (or of the other
 * families' path): argument and family checks; a model whose dims[0] is 1
 * tests its family once more (dims0: its dims[0]). */
void tf_insn_displacements(tf_insn_mix *t, tf_core core, uint32_t dims0);

/* evaluate() for the nodal layout (nodal and contact, p != 1): the
 * projection's call, the family switch, the status. */
void tf_insn_evaluate_nodal(tf_insn_mix *t, tf_core core);

/* tfit_basis() of degree p. */
void tf_insn_basis(tf_insn_mix *t, tf_core core, uint32_t p);

/* tfit_eval_nodal: the basis of degree p, then n_out output points. */
void tf_insn_nodal(tf_insn_mix *t, tf_core core, uint32_t p, uint32_t n_out);

/* tfit_eval_modal: the basis of degree p, r amplitudes, n_out points. */
void tf_insn_modal(tf_insn_mix *t, tf_core core, uint32_t p, uint32_t r, uint32_t n_out);

/* The modal rows in assembly (tfit_modal_armv7em.c), rank r <= 8: the
 * dispatch, the rank's function and its loop over n_out output points (the
 * region surfaces' rows too). */
void tf_insn_modal_rows_asm(tf_insn_mix *t, tf_core core, uint32_t r, uint32_t n_out);

/* tfit_degree1_asm() outside its entry: the projection, n_out points of
 * degree-1 rows (tfit_displacements' nodal p = 1 path). */
void tf_insn_degree1(tf_insn_mix *t, tf_core core, uint32_t n_out);

/* tfit_degree1_rows_asm(): n_out points of degree-1 rows at a projected g. */
void tf_insn_degree1_rows(tf_insn_mix *t, tf_core core, uint32_t n_out);

/* The shared blocks, for the objdump check of their loops. */
extern const tf_block tf_insn_shared[];
extern const size_t tf_insn_n_shared;

#endif /* TF_EVALUATOR_H */
