/* camera.h - chapter 01: generating eye rays.
 *
 * The lecture's camera interface: "generate ray for image position", with
 * normalized coordinates (u, v) in [0,1]^2 so that the camera never has to
 * know the image resolution.  Two projections:
 *   perspective  - same origin, different directions;
 *   orthographic - same direction, different origins.
 */
#ifndef CH01_CAMERA_H
#define CH01_CAMERA_H

#include <stdbool.h>
#include <stddef.h>

#include "ray.h"
#include "scene.h"

/* snippet: camera */
typedef struct {
    camera_kind kind;
    vec3 e;             /* viewPoint: the eye */
    vec3 u, v, w;       /* orthonormal basis: u right, v up, w backwards (-w is viewDir) */
    real d;             /* projDistance: eye to image plane (perspective only) */
    real width, height; /* viewWidth, viewHeight: the image rectangle on that plane */
} camera;
/* end snippet */

/* Builds the camera of a scene description (<camera> in docs/scenes.md).  Returns
 * NULL, or the problem when the camera is degenerate: a zero viewDir or
 * viewUp, viewUp parallel to viewDir, or a size that is not positive. */
const char *camera_init(camera *cam, const scene_camera *desc);

/* camera_init on a whole scene description: returns true, or false with
 * "file:line: camera: problem" in err (the line of the <camera> element). */
bool camera_from_scene(camera *cam, const scene *desc, char *err, size_t err_size);

/* The orthonormal basis from the view direction and the up vector:
 *     w = -viewDir / |viewDir|,  u = (viewDir x viewUp) / |viewDir x viewUp|,  v = w x u.
 * The inputs must be non-zero and not parallel (camera_init checks). */
void camera_basis(vec3 view_dir, vec3 view_up, vec3 *u, vec3 *v, vec3 *w);

/* The eye ray through normalized image position (u, v): (0,0) is the
 * bottom-left corner of the image rectangle, (1,1) the top-right. */
ray camera_ray(const camera *cam, real u, real v);

#endif
