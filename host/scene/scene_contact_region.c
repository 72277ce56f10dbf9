/*
 * scene_contact_region.c — contact regions in scenes (scene_contact_region.h).
 */
#include "scene/scene_contact_region.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "problem/region_chart.h"

/* "contact.K.key" (key NULL: "contact.K") into buf. */
static const char *path_of(char *buf, size_t len, size_t k, const char *key)
{
    if (key != NULL) {
        snprintf(buf, len, "contact.%zu.%s", k, key);
    } else {
        snprintf(buf, len, "contact.%zu", k);
    }
    return buf;
}

int sd_contact_is_region(const sd_contact *d)
{
    return d->region != NULL || d->tip != NULL || d->friction != NULL || d->spacing != NULL;
}

/* The rectangle: a box face's, or an organ's around its centre. */
static int rectangle(const sd_region *d, const tf_problem *s, size_t k, tf_contact_region *r,
                     sd_issue *is)
{
    char p[96];
    int organ = tf_problem_mesh(s) != NULL;
    if (!organ) {
        if (d->face == NULL || d->rect == NULL || d->centre || d->radius || d->size) {
            return sd_fail(is, path_of(p, sizeof p, k, "region"),
                           "on a box a region is {face, rect: [a0, a1, b0, b1]} (centre, radius "
                           "and size place a region on an organ)");
        }
        r->kind = TF_CONTACT_REGION_FACE;
        r->face = (tf_face)*d->face;
        memcpy(r->rect, d->rect, sizeof r->rect);
        return 0;
    }
    if (d->face || d->rect || d->centre == NULL || (d->radius != NULL) == (d->size != NULL)) {
        return sd_fail(is, path_of(p, sizeof p, k, "region"),
                       "on an organ a region is {centre: [x, y, z], radius} or {centre, size: "
                       "[A, B]} (face and rect place a region on a box)");
    }
    r->kind = TF_CONTACT_REGION_ORGAN;
    memcpy(r->centre, d->centre, sizeof r->centre);
    r->size[0] = d->radius ? 2 * *d->radius : d->size[0];
    r->size[1] = d->radius ? 2 * *d->radius : d->size[1];
    return 0;
}

/* The tip the scene's first point contact gives (its patch or site), when
 * the region gives none.  Returns 0, or 1 when there is none. */
static int tip_of_scene(const sd_scene *doc, tf_contact_region *r)
{
    for (size_t j = 0; j < doc->contact_count; ++j) {
        const sd_contact *e = &doc->contact[j];
        if (e->site) {
            r->tip = TF_TIP_DISC;
            r->tip_radius = e->site->radius;
            return 0;
        }
        if (e->patch && e->patch->size) {
            r->tip = TF_TIP_RECT;
            r->tip_size[0] = e->patch->size[0];
            r->tip_size[1] = e->patch->size[1];
            return 0;
        }
        if (e->patch && e->patch->radius) {
            r->tip = TF_TIP_DISC;
            r->tip_radius = *e->patch->radius;
            return 0;
        }
    }
    return 1;
}

static int tip(const sd_scene *doc, size_t k, tf_contact_region *r, sd_issue *is)
{
    char p[96];
    const sd_tip *d = doc->contact[k].tip;
    if (d == NULL) {
        if (tip_of_scene(doc, r) != 0) {
            return sd_fail(is, path_of(p, sizeof p, k, NULL),
                           "a region needs the probe's tip: tip: {radius: r} (or {shape: rect, "
                           "size: [sx, sy]} on a box); no other contact gives a patch to copy");
        }
        return 0;
    }
    r->tip = d->shape ? (tf_tip_shape)*d->shape : d->size ? TF_TIP_RECT : TF_TIP_DISC;
    if ((r->tip == TF_TIP_RECT) != (d->size != NULL) || (r->tip == TF_TIP_DISC) != (d->radius != NULL)) {
        return sd_fail(is, path_of(p, sizeof p, k, "tip"),
                       "a disc tip takes radius, a rect tip takes size: [sx, sy] (mm)");
    }
    if (r->tip == TF_TIP_RECT) {
        if (r->kind != TF_CONTACT_REGION_FACE) {
            return sd_fail(is, path_of(p, sizeof p, k, "tip"),
                           "a rect tip belongs to a box face; on an organ the tip is a disc");
        }
        r->tip_size[0] = d->size[0];
        r->tip_size[1] = d->size[1];
    } else {
        r->tip_radius = *d->radius;
    }
    return 0;
}

int sd_contact_region(const sd_scene *doc, size_t k, const tf_problem *s, tf_contact *c,
                      sd_issue *is)
{
    char p[96];
    const sd_contact *d = &doc->contact[k];
    if (d->region == NULL) {
        return sd_fail(is, path_of(p, sizeof p, k, NULL),
                       "tip, friction and spacing belong to a region: give region too");
    }
    if (d->node || d->at || d->patch || d->site) {
        return sd_fail(is, path_of(p, sizeof p, k, NULL),
                       "a region replaces node, at, patch and site: give one or the other");
    }
    tf_contact_region *r = &c->region;
    memset(r, 0, sizeof *r);
    if (rectangle(d->region, s, k, r, is) != 0 || tip(doc, k, r, is) != 0) {
        return -1;
    }
    r->friction = d->friction ? *d->friction : SD_REGION_FRICTION;
    r->spacing = d->spacing ? *d->spacing : 0;
    if (!(r->friction >= 0)) {
        return sd_fail(is, path_of(p, sizeof p, k, "friction"), "must be a number >= 0");
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    if (tf_region_chart_build(&ctx, s, r) != 0) {
        return sd_fail(is, path_of(p, sizeof p, k, "region"), "%s", ctx.err);
    }
    double len = fmin(r->chart.len[0], r->chart.len[1]);
    if (d->spacing && !(r->spacing <= len / 3)) {
        return sd_fail(is, path_of(p, sizeof p, k, "spacing"),
                       "at most a third of the region's shorter side (%g mm), so that each axis "
                       "has 4 sites or more (got %g mm)", len, r->spacing);
    }
    /* The probe at the domain's centre: the contact point and patch of
     * whatever fits one site. */
    tf_ctx e; /* the patch's message, put in the scene's words */
    tf_ctx_init(&e);
    if (tf_region_site_patch(&e, s, r, 0.5 * r->chart.len[0], 0.5 * r->chart.len[1], &c->patch,
                             c->at) != 0) {
        return sd_fail(is, path_of(p, sizeof p, k, "region"), "%s", e.err);
    }
    c->node = tf_problem_nearest_node(s, c->at);
    c->by_node = 0;
    return 0;
}
