/*
 * scene_history.h — the scene's `history:` section into a problem's load
 * history (problem/history.h): segments checked kind by kind, or a table of
 * forces read from a CSV file next to the scene.
 */
#ifndef TF_SCENE_HISTORY_H
#define TF_SCENE_HISTORY_H

#include "problem/problem.h"
#include "scene/scene_issue.h"
#include "scene/scene_schema.h"

/* Fills p->history from d (NULL: no history).  The contact sites must be
 * resolved already.  Returns 0, or -1 with the issue. */
int sd_history_build(const sd_history *d, tf_problem *p, sd_issue *is);

#endif /* TF_SCENE_HISTORY_H */
