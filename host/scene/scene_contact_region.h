/*
 * scene_contact_region.h — a contact entry that gives a region (the tool may
 * touch anywhere on it) instead of a point: its rectangle on a box face or
 * an organ, the probe's tip, friction and site spacing, checked and
 * resolved to a chart (problem/region_chart.h).
 */
#ifndef TF_SCENE_CONTACT_REGION_H
#define TF_SCENE_CONTACT_REGION_H

#include <stddef.h>

#include "problem/problem.h"
#include "scene/scene_issue.h"
#include "scene/scene_schema.h"

/* Default friction coefficient of a region (spec: 0.3). */
#define SD_REGION_FRICTION 0.3

/* 1 when contact entry d gives any of the region keys (region, tip,
 * friction, spacing). */
int sd_contact_is_region(const sd_contact *d);

/* Contact entry k of doc (a region) into c: c->region (kind, rectangle,
 * tip, friction, spacing, chart) and, as for a contact site, the point,
 * node and patch of the probe at the domain's centre.  Returns 0, or -1
 * with the issue (path contact.K.KEY). */
int sd_contact_region(const sd_scene *doc, size_t k, const tf_problem *s, tf_contact *c,
                      sd_issue *is);

#endif /* TF_SCENE_CONTACT_REGION_H */
