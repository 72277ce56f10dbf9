/*
 * cmd_args.c — option values shared by the solver commands (cmd_args.h).
 */
#include "cli/cmd_args.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/atomic_file.h"
#include "base/log.h"
#include "meshfree/cut.h"

int tf_parse_vec3(const char *s, double v[3])
{
    const char *p = s;
    for (int k = 0; k < 3; ++k) {
        char *end;
        v[k] = strtod(p, &end);
        if (end == p || !isfinite(v[k]) || *end != (k < 2 ? ',' : '\0')) {
            return -1;
        }
        p = end + 1;
    }
    return 0;
}

int tf_sets_add(tf_sets *s, const char *assignment)
{
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 8;
        const char **grown = realloc(s->item, cap * sizeof *grown);
        if (grown == NULL) {
            return -1;
        }
        s->item = grown;
        s->cap = cap;
    }
    s->item[s->n++] = assignment;
    return 0;
}

void tf_sets_free(tf_sets *s)
{
    free(s->item);
    s->item = NULL;
    s->n = s->cap = 0;
}

tf_scene *tf_cmd_scene(tf_ctx *ctx, const char *path, const tf_sets *sets)
{
    tf_scene *s = tf_scene_load(ctx, path, sets->item, sets->n);
    if (s == NULL) {
        tf_error(ctx, "%s", ctx->err);
        return NULL;
    }
    for (const char *line = s->warnings; *line != '\0'; line += strcspn(line, "\n") + 1) {
        tf_warn(ctx, "%.*s", (int)strcspn(line, "\n"), line);
    }
    for (const char *line = s->notes; *line != '\0'; line += strcspn(line, "\n") + 1) {
        tf_info(ctx, "%.*s", (int)strcspn(line, "\n"), line);
    }
    return s;
}

int tf_cmd_outputs(tf_ctx *ctx, const char *cmd, const char *const *paths, size_t n)
{
    for (size_t k = 0; k < n; ++k) {
        if (paths[k] != NULL && tf_afile_check(ctx, paths[k]) != 0) {
            tf_error(ctx, "%s: %s", cmd, ctx->err);
            return -1;
        }
    }
    return 0;
}

int tf_cmd_output_dir(tf_ctx *ctx, const char *cmd, const char *dir)
{
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        tf_error(ctx, "%s: %s: no such directory", cmd, dir);
        return -1;
    }
    if (access(dir, W_OK | X_OK) != 0) {
        tf_error(ctx, "%s: %s: cannot write in it: %s", cmd, dir, strerror(errno));
        return -1;
    }
    return 0;
}

int tf_cmd_cut_progress(tf_ctx *ctx, const char *scene, tf_problem *p, double s)
{
    if (p->n_cuts == 0) {
        tf_error(ctx, "solve: --cut-progress: %s has no cuts", scene);
        return -1;
    }
    size_t kept = 0;
    for (size_t i = 0; i < p->n_cuts; ++i) {
        tf_cut c;
        tf_cut_truncate(&p->cuts[i], s, &c);
        if (c.n >= 2) {
            p->cuts[kept++] = c;
        }
    }
    p->n_cuts = kept;
    return 0;
}
