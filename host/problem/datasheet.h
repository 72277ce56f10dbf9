/*
 * datasheet.h — the physics a generated header encodes, in words: the body
 * and its cloud, the material law and its parameters, the solver, the
 * supports, the contact site and the force envelope.  The header's banner
 * carries it so that a reader can check the model without the scene file.
 */
#ifndef TF_DATASHEET_H
#define TF_DATASHEET_H

#include <stddef.h>

#include "problem/problem.h"

/* Writes the lines (each "  key: text", '\n'-separated, no trailing
 * newline) into buf, truncated to n bytes; contact is the fitted site's
 * index.  Returns the length written. */
size_t tf_problem_datasheet(const tf_problem *p, int contact, char *buf, size_t n);

#endif /* TF_DATASHEET_H */
