/*
 * scene_cut_check.h — a scene's cuts checked against its node cloud before
 * any solve (docs/cutting.md, "What a cut must be"): a cut far shallower or
 * shorter than the node spacing, a path that encloses no area or doubles
 * back on itself, a cut along a face of the box, and a cut that leaves a
 * node's support with too few visible nodes (too few, or all in one plane)
 * are refused at their entry, where a solve would have failed later with a
 * singular local system blamed on the support, or given an answer the cut
 * changed by a visibility artefact.
 */
#ifndef TF_SCENE_CUT_CHECK_H
#define TF_SCENE_CUT_CHECK_H

#include "problem/problem.h"
#include "scene/scene_issue.h"

/* Cuts whose depth, or whose path's length, is under this fraction of the
 * local node spacing are refused. */
#define SD_CUT_MIN_SPACINGS 1e-3

/* Checks s->cuts against s->cloud and s->solver.support.  Returns 0, or -1
 * with the issue at the offending cut's entry. */
int sd_check_cuts(const tf_problem *s, sd_issue *is);

#endif /* TF_SCENE_CUT_CHECK_H */
