/*
 * api.h — the flat C API the Python module (python/tissuefit) binds with
 * ctypes: opaque handles, plain arrays, and the run's context first.
 *
 * Every fallible call takes a context made by tf_api_ctx_new(), returns 0
 * (or a handle) on success and -1 (or NULL) on failure, and leaves the
 * message in the context (tf_api_ctx_error): the text `tissuefit` prints
 * after "tissuefit: error: " for the same scene, values and command, so a
 * broken scene's message names its file, line and field.  The library is
 * built as build/native/libtissuefit.so (host/host.mk) and exports these
 * functions only.
 *
 * The arrays are row-major doubles in the scene's units (mm, N); a node's
 * three values are consecutive, nodes in the scene's node order (node
 * number = index + 1, as in the CSV `tissuefit solve` writes).
 */
#ifndef TF_API_H
#define TF_API_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"

/* ---- the context --------------------------------------------------------- */

/* A context whose messages at or below `level` (0 errors, 1 warnings,
 * 2 progress) go to standard error as the tool writes them, and whose last
 * error is also kept for tf_api_ctx_error.  NULL when out of memory. */
tf_ctx *tf_api_ctx_new(int level);
void tf_api_ctx_free(tf_ctx *ctx);

/* The message of the last failure ("" before any); valid until the next call. */
const char *tf_api_ctx_error(const tf_ctx *ctx);

/* The OpenBLAS kernel family in use, and the one `tissuefit` pins
 * (base/blas_pin.h).  Returns 0 when they agree (the solves give the tool's
 * bits), else -1 with a message saying what to set before the library is
 * loaded.  Also sets OpenBLAS to one thread, as the tool runs it. */
int tf_api_blas_check(tf_ctx *ctx);

/* ---- scenes -------------------------------------------------------------- */

typedef struct tf_api_scene tf_api_scene;

/* The scene file with the n_sets `key=value` overrides of --set applied
 * (warnings go to the context's log).  NULL on failure: the message names
 * the file, line and field as the tool's does. */
tf_api_scene *tf_api_scene_load(tf_ctx *ctx, const char *path, const char *const *sets,
                                size_t n_sets);
void tf_api_scene_free(tf_api_scene *s);

/* Node count; *xyz (when not NULL) points at the 3 n coordinates, mm,
 * valid while the scene lives. */
size_t tf_api_scene_nodes(const tf_api_scene *s, const double **xyz);

/* The scene's outputs: their count; when xyz is not NULL, their 3 n
 * positions (mm) and ids (the node number for outputs at nodes, the point
 * number 1, 2, ... for outputs at points: the `output` column of
 * `tissuefit solve --outputs`). */
size_t tf_api_scene_outputs(const tf_api_scene *s, double *xyz, uint64_t *id);

/* Material regions (the scene's inclusions): their count; when region is
 * not NULL, the region of every node (0 the body, k the k-th inclusion, the
 * first holding the node: the "material" of the tool's VTU files). */
size_t tf_api_scene_regions(const tf_api_scene *s, uint32_t *region);

/* Contact sites: their count, and the name of site k (NULL beyond). */
size_t tf_api_scene_contacts(const tf_api_scene *s);
const char *tf_api_scene_contact_name(const tf_api_scene *s, size_t k);

/* ---- solving --------------------------------------------------------------- */

/* `tissuefit solve SCENE [--force F] [--contact NAME] [--cut-progress S]
 * --outputs ...`: the displacement of every node into u (3 n_nodes) and at
 * the scene's outputs into at_outputs (3 n_outputs; NULL: not wanted), the
 * same bits as the tool's CSV files.  force NULL: no --force (the scene's
 * own loads); contact NULL: the first site; cut_progress NaN: no
 * --cut-progress (the scene's cuts whole), else S in [0, 1].  The solver is
 * built at the first solve and kept for the next ones at the same cut
 * progress (each solve is one load case from rest, as the tool's).  A scene
 * with a history: section is refused (tf_api_solve_history solves it). */
int tf_api_solve(tf_ctx *ctx, tf_api_scene *s, const char *contact, const double *force,
                 double cut_progress, double *u, double *at_outputs);

/* `tissuefit solve SCENE [--force F] [--contact NAME]` of a scene with a
 * history: section, in two calls: tf_api_history_steps gives the number of
 * steps n, then tf_api_solve_history fills the times t (n), every node's
 * displacements u (n x 3 n_nodes) and the outputs' at_outputs (n x 3
 * n_outputs; NULL: not wanted), the bits of the tool's CSV.  force NULL:
 * history.force, else the force that replaces it (refused for a table of
 * forces, as the tool refuses --force); contact NULL: history.contact.
 * Each call starts from rest on a solver built afresh: a second run of a
 * nonlinear solver reset to rest (tf_nonlinear_reset) differs from the
 * first in the last bits, so something it keeps is not reset. */
int tf_api_history_steps(tf_ctx *ctx, tf_api_scene *s, const double *force, size_t *n);
int tf_api_solve_history(tf_ctx *ctx, tf_api_scene *s, const char *contact, const double *force,
                         double *t, double *u, double *at_outputs);

/* The displacement field of a solution u (from tf_api_solve of this scene)
 * at np points xyz (3 np, mm) into out (3 np): what an output at those
 * points gives (solvers/probe.h). */
int tf_api_field(tf_ctx *ctx, tf_api_scene *s, const double *u, const double *xyz, size_t np,
                 double *out);

/* The cells of the VTU file `tissuefit solve --vtk` writes for the scene:
 * their count and corners per cell (8: VTK hexahedra of the grid, without
 * those a cut passes through; 4: an organ's tetrahedra).  conn NULL: the
 * count only; else conn receives corners x count node indices (from 0). */
int tf_api_cells(tf_ctx *ctx, const tf_api_scene *s, size_t *count, unsigned *corners,
                 uint64_t *conn);

/* ---- fitting --------------------------------------------------------------- */

/* `tissuefit fit ARGS...` run in this process, by the tool's own command
 * (cli/cmd_fit.c): args are the words after `fit` (the scene, -o FILE.h,
 * --set KEY=VALUE, ...).  Returns 0 when the header and its golden file
 * were written, else -1 with the message; *status (when not NULL) is the
 * tool's exit status (0; 1 a failure while running; 2 bad usage or a scene
 * that cannot be fitted, nothing written).  The command parses its words
 * with getopt, whose state is the process's: one fit at a time. */
int tf_api_fit(tf_ctx *ctx, const char *const *args, size_t n_args, int *status);

#endif /* TF_API_H */
