/*
 * scene_refused.h — a small good scene (t.yaml) and checks that variants of
 * it, or any scene text, are refused with the expected message fragments
 * (file:line:field and the reason).  Shared by the scene tests.
 */
#ifndef TF_SCENE_REFUSED_H
#define TF_SCENE_REFUSED_H

#include <stddef.h>

/* 14 lines: a 10 x 10 x 2 mm box, E 1, nu 0.3, z- clamped, contact node 13,
 * outputs on z+.  Loads as "t.yaml". */
extern const char *const tf_test_scene;

/* tf_test_scene with lines line .. line + span - 1 replaced by replacement
 * must be refused with every fragment (NULL-terminated) in the message;
 * fails the current cmocka test otherwise. */
void tf_test_refused(int line, int span, const char *replacement, const char *const *fragments);

/* The same for any scene text of len bytes. */
void tf_test_refused_text(const char *text, size_t len, const char *const *fragments);

#endif /* TF_SCENE_REFUSED_H */
