/*
 * scene_held.h — do a scene's fixed regions hold its body, and leave it
 * something to move?  A clamp of every node leaves nothing to solve; fixed
 * regions that together stop fewer than the six rigid motions (a clamp of
 * one node: the body turns about it) leave the stiffness singular.  Both
 * failed in the solver without naming the entry; here they are refused at
 * it (file:line).
 */
#ifndef TF_SCENE_HELD_H
#define TF_SCENE_HELD_H

#include "problem/problem.h"
#include "scene/scene_issue.h"

/* Checks s->fixed against s->cloud.  Returns 0, or -1 with the issue at the
 * fixed entry to blame (the one holding every node, or the last one when
 * together they leave a rigid motion free). */
int sd_check_held(const tf_problem *s, sd_issue *is);

#endif /* TF_SCENE_HELD_H */
