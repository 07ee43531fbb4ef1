/* camera.c - chapter 01: the camera basis and eye rays. */
#include "01_camera_rays/camera.h"
#include "exercise.h"

#include <stdio.h>

#include "explain.h"

/* Scales a by its largest component before normalizing, so that vectors with
 * huge or tiny components neither overflow nor underflow in the dot product. */
static vec3 unit(vec3 a) { return vec3_normalize(vec3_scale(a, 1 / vec3_max_abs(a))); }

void camera_basis(vec3 view_dir, vec3 view_up, vec3 *u, vec3 *v, vec3 *w)
{
    /* TODO basis: the orthonormal basis u (right), v (up), w (backwards) from viewDir and viewUp
     * (README, "The basis", which also says which products can overflow and how unit() avoids it). */
    EXERCISE_STUB("01_camera_rays", "camera.c", "basis"); /* delete this line when done */
    (void)view_dir, (void)view_up;
    *u = vec3_make(0, 0, 0);
    *v = vec3_make(0, 0, 0);
    *w = vec3_make(0, 0, 0);
}

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

ray camera_ray(const camera *cam, real u, real v)
{
    /* TODO rays: the eye ray through (u, v), for both kinds of camera: first the point of the image
     * rectangle that (u, v) names, then the ray of the projection (README, "The rays"). */
    EXERCISE_STUB("01_camera_rays", "camera.c", "rays"); /* delete this line when done */
    (void)u, (void)v;
    ray r = {cam->e, vec3_make(0, 0, 0)};
    EXPLAIN(explain_eye_ray(r));
    return r;
}
