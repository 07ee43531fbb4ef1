/* camera.c - chapter 01: the camera basis and eye rays. */
#include "01_camera_rays/camera.h"
#include "exercise.h"

#include <stdio.h>

/* Scales a by its largest component before normalizing, so that vectors with
 * huge or tiny components neither overflow nor underflow in the dot product. */
static vec3 unit(vec3 a) { return vec3_normalize(vec3_scale(a, 1 / vec3_max_abs(a))); }

/* snippet: basis */
void camera_basis(vec3 view_dir, vec3 view_up, vec3 *u, vec3 *v, vec3 *w)
{
    /* TODO basis: the camera's orthonormal basis (lecture, "Specifying views"; <camera> in docs/scenes.md):
     *     w = -viewDir / |viewDir|
     *     u = (viewDir x viewUp) / |viewDir x viewUp|
     *     v = w x u
     * Normalize with unit(), which also copes with very large or small vectors; take the cross
     * product of unit(viewDir) and unit(viewUp), not of the raw vectors, whose products can
     * overflow (or underflow to 0) before unit() sees them. */
    EXERCISE_STUB("01_camera_rays", "camera.c", "basis"); /* delete this line when done */
    (void)view_dir;
    (void)view_up;
    *u = vec3_make(0, 0, 0);
    *v = vec3_make(0, 0, 0);
    *w = vec3_make(0, 0, 0);
}
/* end snippet */

const char *camera_init(camera *cam, const scene_camera *desc)
{
    if (vec3_max_abs(desc->view_dir) == 0)
        return "viewDir is the zero vector";
    if (vec3_max_abs(desc->view_up) == 0)
        return "viewUp is the zero vector";
    /* |sin| of the angle between viewDir and viewUp.  Below sqrt(epsilon) the
     * cross product that gives u has lost half its significant digits. */
    real sine = vec3_length(vec3_cross(unit(desc->view_dir), unit(desc->view_up)));
    if (!(sine > real_sqrt(REAL_EPSILON)))
        return "viewUp is parallel to viewDir, so 'up' does not fix the camera's roll";
    if (!(desc->view_width > 0))
        return "viewWidth must be positive";
    if (!(desc->view_height > 0))
        return "viewHeight must be positive";
    if (desc->kind == CAMERA_PERSPECTIVE && !(desc->proj_distance > 0))
        return "projDistance must be positive";

    cam->kind = desc->kind;
    cam->e = desc->view_point;
    cam->d = desc->proj_distance;
    cam->width = desc->view_width;
    cam->height = desc->view_height;
    camera_basis(desc->view_dir, desc->view_up, &cam->u, &cam->v, &cam->w);
    return NULL;
}

bool camera_from_scene(camera *cam, const scene *desc, char *err, size_t err_size)
{
    const char *problem = camera_init(cam, &desc->camera);
    if (problem)
        snprintf(err, err_size, "%s:%d: camera: %s", scene_name(desc), desc->camera.line, problem);
    return problem == NULL;
}

/* snippet: camera_ray */
ray camera_ray(const camera *cam, real u, real v)
{
    /* Where (u, v) lies on the image rectangle, in the basis u, v, centred
     * on the view direction: from -width/2 to width/2, -height/2 to height/2. */
    real us = (u - (real)0.5) * cam->width;
    real vs = (v - (real)0.5) * cam->height;
    vec3 offset = vec3_add(vec3_scale(cam->u, us), vec3_scale(cam->v, vs));
    ray r;
    if (cam->kind == CAMERA_PERSPECTIVE) {
        /* TODO perspective: perspective projection, "same origin, different directions":
         *     p = e,   d = -d w + us u + vs v   (d: the projection distance; us u + vs v is `offset`)
         * Do not normalize d: then t = 1 is the image plane. */
        EXERCISE_STUB("01_camera_rays", "camera.c", "perspective"); /* delete this line when done */
        (void)offset;
        r.p = cam->e;
        r.d = vec3_make(0, 0, 0);
    } else {
        /* TODO orthographic: parallel projection, "same direction, different origins":
         *     p = e + us u + vs v,   d = -w */
        EXERCISE_STUB("01_camera_rays", "camera.c", "orthographic"); /* delete this line when done */
        r.p = cam->e;
        r.d = vec3_make(0, 0, 0);
    }
    return r;
}
/* end snippet */
