/*
 * scene_ranges.c — the range of every number in a scene (scene_ranges.h).
 */
#include "scene/scene_ranges.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Any number: 0 or within these magnitudes.  Products of a few such values
 * (E h, F / (E h), penalty x stiffness) stay far inside a double, and the
 * displacements a fitted model outputs inside a float. */
#define SD_TINY 1e-15
#define SD_HUGE 1e15

/* Lengths (mm) and forces (N): a kilometre and a meganewton bound what a
 * tissue scene can mean by a wide margin. */
#define SD_MM 1e6
#define SD_N 1e6

typedef struct sd_range {
    const char *pattern; /* a path; '*' stands for any one component */
    double lo, hi;
    const char *what;    /* "... in [lo, hi] (got v)" */
    int replaces;        /* 1: this range replaces the magnitude rule (a tolerance is
                          * compared, never multiplied, so it may be very small) */
} sd_range;

static const sd_range ranges[] = {
    {"material.E", 1e-9, 1e12, "Young's modulus must be a positive number of MPa", 0},
    {"envelope.radius", 1e-9, SD_N, "the envelope radius must be a positive number of newtons", 0},
    {"envelope.centre.*", -SD_N, SD_N, "the envelope centre must be a force (N)", 0},
    {"loads.*.force.*", -SD_N, SD_N, "a load must be a force (N)", 0},
    {"geometry.box.*.*", -SD_MM, SD_MM, "coordinates must be numbers of mm", 0},
    {"fixed.*.box.*.*", -SD_MM, SD_MM, "coordinates must be numbers of mm", 0},
    {"fixed.*.plane.at", -SD_MM, SD_MM, "coordinates must be numbers of mm", 0},
    {"fixed.*.displacement.*", -SD_MM, SD_MM, "displacements must be numbers of mm", 0},
    {"outputs.box.*.*", -SD_MM, SD_MM, "coordinates must be numbers of mm", 0},
    {"loads.*.patch.*.*", -SD_MM, SD_MM, "patch coordinates must be numbers of mm", 0},
    {"loads.*.patch.radius", -SD_MM, SD_MM, "a patch radius must be a number of mm", 0},
    {"contact.*.patch.*.*", -SD_MM, SD_MM, "patch coordinates must be numbers of mm", 0},
    {"contact.*.patch.radius", -SD_MM, SD_MM, "a patch radius must be a number of mm", 0},
    {"contact.*.region.rect.*", -SD_MM, SD_MM, "a region's rectangle must be numbers of mm", 0},
    {"contact.*.region.centre.*", -SD_MM, SD_MM, "a region's centre must be a point (mm)", 0},
    {"contact.*.region.radius", 1e-6, SD_MM, "a region's radius must be a positive number of mm",
     0},
    {"contact.*.region.size.*", 1e-6, SD_MM, "a region's sides must be positive numbers of mm", 0},
    {"contact.*.tip.radius", 1e-6, SD_MM, "the tip's radius must be a positive number of mm", 0},
    {"contact.*.tip.size.*", 1e-6, SD_MM, "the tip's sides must be positive numbers of mm", 0},
    {"contact.*.friction", 0, 100, "the friction coefficient must be a number >= 0", 0},
    {"contact.*.spacing", 1e-6, SD_MM, "the site spacing must be a positive number of mm", 0},
    {"solver.support", 1e-3, 100, "the support radius must be a number of nodal spacings", 0},
    {"solver.rbf.alpha_c", -1e6, 1e6, "alpha_c must be a number", 0},
    {"solver.rbf.d_c", -SD_MM, SD_MM, "d_c must be a number of mm", 0},
    {"solver.rbf.q", -10, 10, "the multiquadric exponent q must be a number", 0},
    {"solver.newton.tolerance", 1e-30, 1, "a relative tolerance must be a number", 1},
    {"solver.newton.energy_tolerance", 1e-30, 1, "a relative tolerance must be a number", 1},
};

/* Whether path matches pattern, component by component. */
static int matches(const char *pattern, const char *path)
{
    while (*pattern != '\0' && *path != '\0') {
        size_t lp = strcspn(pattern, "."), lq = strcspn(path, ".");
        if (!(lp == 1 && pattern[0] == '*') && (lp != lq || strncmp(pattern, path, lp) != 0)) {
            return 0;
        }
        pattern += lp + (pattern[lp] == '.');
        path += lq + (path[lq] == '.');
    }
    return *pattern == '\0' && *path == '\0';
}

int sd_range_check(const char *path, double v, char *msg, size_t msglen)
{
    for (size_t k = 0; k < sizeof ranges / sizeof ranges[0]; ++k) {
        const sd_range *r = &ranges[k];
        if (!matches(r->pattern, path)) {
            continue;
        }
        if (!(v >= r->lo && v <= r->hi)) {
            snprintf(msg, msglen, "%s in [%g, %g] (got %g)", r->what, r->lo, r->hi, v);
            return -1;
        }
        if (r->replaces) {
            return 0;
        }
    }
    if (!(fabs(v) <= SD_HUGE) || (v != 0 && fabs(v) < SD_TINY)) {
        snprintf(msg, msglen, "numbers in a scene are 0 or between %g and %g in magnitude (got %g)",
                 SD_TINY, SD_HUGE, v);
        return -1;
    }
    return 0;
}
