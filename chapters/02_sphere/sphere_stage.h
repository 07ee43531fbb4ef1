/* sphere_stage.h - chapter 02: what its renderer traces, and the built-in scene. */
#ifndef CH02_SPHERE_STAGE_H
#define CH02_SPHERE_STAGE_H

#include "01_camera_rays/camera.h"
#include "02_sphere/sphere.h"
#include "scene.h"

/* The camera, the scene's spheres (other surfaces are named as ignored) and <backColor>. */
typedef struct {
    camera cam;
    sphere *spheres;
    int n_spheres;
    color background;
    int formula; /* what render.c's --sphere chose: prepare's context, an int */
} sphere_stage;

/* The lecture's slide: Sphere((0.0, 0.0, 0.0), 1.0), seen from 4 units
 * away.  0, or -1 when out of memory. */
int sphere_stage_scene(scene *desc);

/* renderer.h's prepare and release for a sphere_stage. */
void *sphere_stage_prepare(const void *context, const scene *desc, char *err, size_t err_size);
void sphere_stage_release(void *prepared);

#endif
