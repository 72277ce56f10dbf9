/*
 * scene_refused.c — see scene_refused.h.
 */
#include "scene_refused.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "scene/scene.h"

const char *const tf_test_scene =
    "name: t\n"                                   /* 1 */
    "geometry:\n"                                 /* 2 */
    "  box: {min: [0, 0, 0], max: [10, 10, 2]}\n" /* 3 */
    "  grid: [5, 5, 2]\n"                         /* 4 */
    "material:\n"                                 /* 5 */
    "  E: 1.0\n"                                  /* 6 */
    "  nu: 0.3\n"                                 /* 7 */
    "fixed:\n"                                    /* 8 */
    "  - face: z-\n"                              /* 9 */
    "contact:\n"                                  /* 10 */
    "  - node: 13\n"                              /* 11 */
    "outputs:\n"                                  /* 12 */
    "  select: face\n"                            /* 13 */
    "  face: z+\n";                               /* 14 */

void tf_test_refused_text(const char *text, size_t len, const char *const *fragments)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load_text(&ctx, text, len, "t.yaml", NULL, 0);
    if (s != NULL) {
        tf_scene_free(s);
        fail_msg("accepted a bad scene: %.*s", (int)len, text);
    }
    for (const char *const *f = fragments; *f; ++f) {
        if (strstr(ctx.err, *f) == NULL) {
            fail_msg("message '%s' lacks '%s'", ctx.err, *f);
        }
    }
}

void tf_test_refused(int line, int span, const char *replacement, const char *const *fragments)
{
    char text[4096] = "";
    size_t used = 0;
    const char *p = tf_test_scene;
    for (int l = 1; *p; ++l) {
        size_t len = (size_t)(strchr(p, '\n') - p) + 1;
        const char *put = l == line ? replacement : l < line || l >= line + span ? p : "";
        size_t n = l == line ? strlen(replacement) : l < line || l >= line + span ? len : 0;
        if (used + n < sizeof text) {
            memcpy(text + used, put, n);
            used += n;
        }
        p += len;
    }
    tf_test_refused_text(text, used, fragments);
}
