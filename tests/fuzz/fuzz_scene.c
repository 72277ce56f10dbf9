/*
 * fuzz_scene.c — libFuzzer target: arbitrary bytes as a scene file
 * (tf_scene_load_text: the strict pass, libcyaml, error wording, build and
 * regions).  Built with ASan + UBSan; a crash, a leak, undefined behaviour
 * or a run over the time limit is a finding.  tests/fuzz.mk runs it.
 */
#include <stddef.h>
#include <stdint.h>

#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load_text(&ctx, (const char *)data, size, "fuzz.yaml", NULL, 0);
    tf_scene_free(s);
    return 0;
}
