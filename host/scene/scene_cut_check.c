/*
 * scene_cut_check.c — a scene's cuts against its node cloud
 * (scene_cut_check.h).
 */
#include "scene/scene_cut_check.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "meshfree/cut.h"
#include "meshfree/neighbours.h"
#include "problem/nodes.h"

static double path_length(const tf_cut *c)
{
    double len = 0;
    for (size_t i = 1; i < c->n; ++i) {
        len += hypot(c->xy[i][0] - c->xy[i - 1][0], c->xy[i][1] - c->xy[i - 1][1]);
    }
    return len;
}

/* A cut far below the node spacing: visibility does not weigh how deep or
 * long a panel is, so a panel 1e-15 mm deep hides nodes as a real one
 * would and changes the answer by percents (docs/cutting.md). */
static int too_small(const tf_problem *s, size_t k, sd_issue *is)
{
    const tf_cut *c = &s->cuts[k];
    const double at[3] = {c->xy[0][0], c->xy[0][1], c->top};
    double h[3];
    char p[64];
    tf_cloud_local_spacing(&s->cloud, at, h);
    if (c->depth < SD_CUT_MIN_SPACINGS * h[2]) {
        snprintf(p, sizeof p, "cuts.%zu.depth", k);
        return sd_fail(is, p,
                       "%g mm deep, under %g of the node spacing there (%g mm): the solve "
                       "cannot resolve it, yet it would hide nodes as a deep cut does (make it "
                       "deeper, or leave it out)",
                       c->depth, SD_CUT_MIN_SPACINGS, h[2]);
    }
    double len = path_length(c), hxy = fmin(h[0], h[1]);
    if (len < SD_CUT_MIN_SPACINGS * hxy) {
        snprintf(p, sizeof p, "cuts.%zu.path", k);
        return sd_fail(is, p,
                       "%g mm long, under %g of the node spacing there (%g mm): the solve "
                       "cannot resolve it, yet it would hide nodes as a long cut does (make it "
                       "longer, or leave it out)",
                       len, SD_CUT_MIN_SPACINGS, hxy);
    }
    return 0;
}

/* A path that folds onto itself: a segment going back along the one before
 * (two panels on one another), or a closed path enclosing no area. */
static int degenerate(const tf_cut *c, size_t k, sd_issue *is)
{
    char p[64];
    for (size_t i = 2; i < c->n; ++i) {
        double u[2] = {c->xy[i - 1][0] - c->xy[i - 2][0], c->xy[i - 1][1] - c->xy[i - 2][1]};
        double v[2] = {c->xy[i][0] - c->xy[i - 1][0], c->xy[i][1] - c->xy[i - 1][1]};
        double cross = u[0] * v[1] - u[1] * v[0], dot = u[0] * v[0] + u[1] * v[1];
        if (dot < 0 && fabs(cross) <= 1e-12 * hypot(u[0], u[1]) * hypot(v[0], v[1])) {
            snprintf(p, sizeof p, "cuts.%zu.path.%zu", k, i);
            return sd_fail(is, p,
                           "the path doubles back along the segment before: two panels on one "
                           "another cut nothing the first does not (a degenerate cut)");
        }
    }
    int closed = c->n >= 3 && c->xy[0][0] == c->xy[c->n - 1][0] &&
                 c->xy[0][1] == c->xy[c->n - 1][1];
    if (closed) {
        double area = 0, len = path_length(c);
        for (size_t i = 1; i < c->n; ++i) {
            area += c->xy[i - 1][0] * c->xy[i][1] - c->xy[i][0] * c->xy[i - 1][1];
        }
        if (fabs(0.5 * area) <= 1e-9 * len * len) {
            snprintf(p, sizeof p, "cuts.%zu.path", k);
            return sd_fail(is, p,
                           "a closed path that encloses no area (%g mm^2): its panels lie on "
                           "one another (a degenerate cut)",
                           0.5 * area);
        }
    }
    return 0;
}

/* A cut along a face of the box (every point on x = min, x = max, y = min
 * or y = max) cuts nothing: it hides the face's nodes from the body. */
static int along_a_face(const tf_problem *s, size_t k, sd_issue *is)
{
    const tf_cut *c = &s->cuts[k];
    const tf_box_geometry *b = &s->geometry.as.box;
    for (int a = 0; a < 2; ++a) {
        for (int side = 0; side < 2; ++side) {
            const double at = side ? b->max[a] : b->min[a];
            size_t on = 0;
            while (on < c->n && c->xy[on][a] == at) {
                on++;
            }
            if (on == c->n) {
                char p[64];
                snprintf(p, sizeof p, "cuts.%zu.path", k);
                return sd_fail(is, p,
                               "runs along the box's %c%c face (%c = %g): a cut there cuts "
                               "nothing and hides the face's nodes from the body",
                               "xy"[a], side ? '+' : '-', "xy"[a], at);
            }
        }
    }
    return 0;
}

/* Whether the m index-space points pts (3 m) span three dimensions: their
 * covariance's determinant against its mean eigenvalue cubed. */
static int spans_3d(const double *pts, size_t m)
{
    if (m < 4) {
        return 0;
    }
    double mean[3] = {0, 0, 0}, c[3][3] = {{0}};
    for (size_t i = 0; i < m; ++i) {
        for (int a = 0; a < 3; ++a) {
            mean[a] += pts[3 * i + a] / (double)m;
        }
    }
    for (size_t i = 0; i < m; ++i) {
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                c[a][b] += (pts[3 * i + a] - mean[a]) * (pts[3 * i + b] - mean[b]);
            }
        }
    }
    double det = c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
                 c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
                 c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0]);
    double tr = (c[0][0] + c[1][1] + c[2][2]) / 3;
    return tr > 0 && det > 1e-9 * tr * tr * tr;
}

typedef struct support_scan {
    tf_cut_set set;
    tf_nbr nbr;
    double *xi;   /* 3 n index-space coordinates */
    uint32_t *idx;
    double *seen; /* 3 cap index-space coordinates of the visible nodes */
    size_t cap;
} support_scan;

static void scan_free(support_scan *sc)
{
    tf_cut_set_free(&sc->set);
    tf_nbr_free(&sc->nbr);
    free(sc->xi);
    free(sc->idx);
    free(sc->seen);
}

/* The support of node i as the solver's shape functions take it (a ball of
 * radius solver.support in index space, shape.c), its nodes in sc->idx;
 * returns their count, or SIZE_MAX when out of memory. */
static size_t support_of(support_scan *sc, size_t i)
{
    size_t n = tf_nbr_query(&sc->nbr, sc->xi + 3 * i, sc->idx, sc->cap);
    if (n > sc->cap) {
        free(sc->idx);
        free(sc->seen);
        sc->cap = 2 * n;
        sc->idx = malloc(sc->cap * sizeof *sc->idx);
        sc->seen = malloc(3 * sc->cap * sizeof *sc->seen);
        if (sc->idx == NULL || sc->seen == NULL) {
            return SIZE_MAX;
        }
        n = tf_nbr_query(&sc->nbr, sc->xi + 3 * i, sc->idx, sc->cap);
    }
    return n;
}

/* Node i's support, past the cuts: the nodes it sees must be four or more
 * and not in one plane, or the local systems about it are singular. */
static int node_sees_enough(support_scan *sc, const tf_problem *s, size_t i, sd_issue *is)
{
    const double *xyz = s->cloud.xyz, *x = xyz + 3 * i;
    size_t n = support_of(sc, i), m = 0;
    if (n == SIZE_MAX) {
        return sd_fail(is, "cuts", "out of memory");
    }
    double reach = 0;
    for (size_t j = 0; j < n; ++j) {
        const double *y = xyz + 3 * (size_t)sc->idx[j];
        reach = fmax(reach, hypot(hypot(y[0] - x[0], y[1] - x[1]), y[2] - x[2]));
    }
    if (tf_cut_set_distance(&sc->set, x) > reach) {
        return 0; /* no cut meets this support */
    }
    for (size_t j = 0; j < n; ++j) {
        if (tf_cut_visible(&sc->set, xyz + 3 * (size_t)sc->idx[j], x)) {
            for (int a = 0; a < 3; ++a) {
                sc->seen[3 * m + (size_t)a] = sc->xi[3 * (size_t)sc->idx[j] + (size_t)a];
            }
            m++;
        }
    }
    if (spans_3d(sc->seen, m)) {
        return 0;
    }
    size_t hidden = 0, c = tf_cut_hiding(&sc->set, xyz, sc->idx, n, x, &hidden);
    if (c == SIZE_MAX) {
        return 0; /* not the cuts' doing: the solver says what is wrong */
    }
    char p[64];
    snprintf(p, sizeof p, "cuts.%zu.path", c);
    return sd_fail(is, p,
                   "hides %zu of the %zu nodes in the support of node %zu at (%g, %g, %g) mm; "
                   "the %zu it still sees are %s, so the local systems there are singular (a "
                   "cut within a node spacing of a face or of another cut leaves a sliver "
                   "without nodes: move the cut, or raise solver.support)",
                   hidden, n, i + 1, x[0], x[1], x[2], m,
                   m < 4 ? "fewer than four" : "all in one plane");
}

static int supports_see_enough(const tf_problem *s, sd_issue *is)
{
    support_scan sc = {.cap = 256};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const size_t n = s->cloud.n;
    const double unit[3] = {s->solver.support, s->solver.support, s->solver.support};
    sc.xi = malloc((3 * n + 1) * sizeof *sc.xi);
    sc.idx = malloc(sc.cap * sizeof *sc.idx);
    sc.seen = malloc(3 * sc.cap * sizeof *sc.seen);
    int rc = sc.xi && sc.idx && sc.seen ? 0 : sd_fail(is, "cuts", "out of memory");
    if (rc == 0 && tf_cut_set_build(&ctx, &sc.set, s->cuts, s->n_cuts) != 0) {
        rc = sd_fail(is, "cuts", "%s", ctx.err);
    }
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            sc.xi[3 * i + (size_t)a] =
                tf_cloud_to_index(&s->cloud, a, s->cloud.xyz[3 * i + (size_t)a]);
        }
    }
    if (rc == 0 && tf_nbr_build(&sc.nbr, sc.xi, n, unit) != 0) {
        rc = sd_fail(is, "cuts", "out of memory");
    }
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        rc = node_sees_enough(&sc, s, i, is);
    }
    scan_free(&sc);
    return rc;
}

int sd_check_cuts(const tf_problem *s, sd_issue *is)
{
    if (s->n_cuts == 0) {
        return 0;
    }
    for (size_t k = 0; k < s->n_cuts; ++k) {
        if (too_small(s, k, is) != 0 || degenerate(&s->cuts[k], k, is) != 0 ||
            along_a_face(s, k, is) != 0) {
            return -1;
        }
    }
    return supports_see_enough(s, is);
}
