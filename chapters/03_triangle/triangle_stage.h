/* triangle_stage.h - chapter 03: what its renderer traces, and its built-in scene.
 *
 * The scene's triangles, each pixel coloured by the barycentric coordinates
 * of the closest hit, (R, G, B) = (alpha, beta, gamma), with the test that
 * --triangle chose.  render.c hands these to renderer_main; the chapter's
 * lab calls them too.
 */
#ifndef CH03_TRIANGLE_STAGE_H
#define CH03_TRIANGLE_STAGE_H

#include <stdint.h>

#include "01_camera_rays/camera.h"
#include "03_triangle/triangle.h"
#include "renderer.h"

typedef struct {
    camera cam;
    triangle *tris; /* the scene's Triangle surfaces */
    int n;
    color back;         /* <backColor> */
    triangle_test test; /* what --triangle chose */
} triangle_stage;

/* The row of --triangle=cramer|watertight aimed at *choice (a triangle_test),
 * for this renderer and every later one. */
knob triangle_knob(int *choice);

/* The closest hit among all triangles with test t: the index of its
 * triangle, or -1 for none. */
int triangle_stage_closest(const triangle_stage *s, ray r, triangle_test t, triangle_hit *best);

/* (R, G, B) = (alpha, beta, gamma) of a hit. */
color barycentric_color(triangle_hit h);

/* renderer.h's prepare, sample and release for a triangle_stage. */
void *triangle_stage_prepare(const void *context, const scene *desc, char *err, size_t err_size);
color triangle_stage_sample(const void *prepared, real u, real v, uint64_t *rays);
void triangle_stage_release(void *prepared);

/* Chapter 03's renderer: the knob, the built-in scene and the functions
 * above, with chapter 01's pixel_to_image. */
renderer triangle_stage_renderer(void);

#endif
