/*
 * transform.h — placing a surface read in file units into the scene's
 * millimetre frame:
 *
 *     x_mm = R (scale x_file - c) + translate
 *
 * where c is the centre of the scaled bounding box when `centre` is set
 * (else 0) and R the rotation by `angle_deg` degrees about `axis`
 * (right-handed, Rodrigues' formula; axis need not be unit length, a zero
 * axis or angle means no rotation).  Scale first, so that `translate` is in
 * millimetres; centring before rotating, so that the organ turns about its
 * own middle.
 */
#ifndef TF_TRANSFORM_H
#define TF_TRANSFORM_H

#include "geometry/geom_msg.h"
#include "geometry/surface.h"

typedef struct tf_transform {
    double scale;        /* file units -> mm, > 0 (1 when the file is in mm) */
    int centre;          /* move the bounding-box centre to the origin */
    double axis[3];      /* rotation axis */
    double angle_deg;    /* rotation angle, degrees */
    double translate[3]; /* mm, applied last */
} tf_transform;

/* scale 1, no centring, no rotation, no translation. */
tf_transform tf_transform_identity(void);

/* The rotation matrix R (row-major). */
void tf_transform_rotation(const tf_transform *t, double r[3][3]);

/* Applies t to every vertex.  Returns TF_GEOM_BAD_INPUT for a scale that
 * is not a positive finite number or a non-finite angle/translation. */
int tf_transform_apply(const tf_transform *t, tf_surface *s, tf_geom_msg *m);

#endif /* TF_TRANSFORM_H */
