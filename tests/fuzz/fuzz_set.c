/*
 * fuzz_set.c — libFuzzer target: arbitrary `--set` arguments on block48.
 * The input is split at newlines into up to 8 assignments applied in order
 * (scene_set.c: paths, list indices, appended entries, flow values, and the
 * rewording of libcyaml's errors in scene_locate.c).  Built with ASan +
 * UBSan; tests/fuzz.mk runs it from the repository root.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene.h"

#define MAX_SETS 8

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char *scene;
static size_t scene_len;

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    FILE *f = fopen("tests/solver/block48_seed.yaml", "rb");
    scene = malloc(1 << 16);
    if (f == NULL || scene == NULL) {
        fprintf(stderr, "fuzz_set: run from the repository root (tests/solver/block48_seed.yaml)\n");
        exit(2);
    }
    scene_len = fread(scene, 1, 1 << 16, f);
    fclose(f);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *sets[MAX_SETS];
    size_t n = 0;
    if (text == NULL) {
        return 0;
    }
    memcpy(text, data, size);
    text[size] = '\0';
    for (char *p = text; p != NULL && n < MAX_SETS; ++n) {
        sets[n] = p;
        p = strchr(p, '\n');
        if (p != NULL) {
            *p++ = '\0';
        }
    }
    tf_scene_free(tf_scene_load_text(&ctx, scene, scene_len, "block48.yaml", sets, n));
    free(text);
    return 0;
}
