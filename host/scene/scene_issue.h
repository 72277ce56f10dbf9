/*
 * scene_issue.h — what is wrong in a scene and where: the path of the
 * offending value (scene_schema.h syntax) and a message.  Its own header so
 * that the builder's helpers (scene_history, scene_organ, ...) report
 * issues without including the builder that includes them.
 */
#ifndef TF_SCENE_ISSUE_H
#define TF_SCENE_ISSUE_H

typedef struct sd_issue {
    char path[128];
    char msg[768]; /* room for a geometry message (geom_msg.h) and its context */
} sd_issue;

/* Records the issue at path (a printf format); returns -1. */
int sd_fail(sd_issue *is, const char *path, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif /* TF_SCENE_ISSUE_H */
