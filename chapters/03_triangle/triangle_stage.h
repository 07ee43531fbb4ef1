/* triangle_stage.h - chapter 03: what its renderer traces (the lab calls it too). */
#ifndef CH03_TRIANGLE_STAGE_H
#define CH03_TRIANGLE_STAGE_H

#include "01_camera_rays/camera.h"
#include "03_triangle/triangle.h"
#include "renderer.h"

typedef struct {
    camera cam;
    color back;         /* <backColor> */
    triangle_test test; /* what --triangle chose */
    int n;
    triangle tris[];    /* the scene's n Triangle surfaces */
} triangle_stage;

/* The row of --triangle=cramer|watertight aimed at *choice, for every renderer from here on. */
knob triangle_knob(int *choice);

/* The closest hit among all triangles with test t: its triangle's index, or -1 for none. */
int triangle_stage_closest(const triangle_stage *s, ray r, triangle_test t, triangle_hit *best);

/* (R, G, B) = (alpha, beta, gamma) of a hit. */
color barycentric_color(triangle_hit h);

/* renderer.h's prepare (context: --triangle's int) and sample (release: free). */
void *triangle_stage_prepare(const void *context, const scene *desc, char *err, size_t err_size);
color triangle_stage_sample(const void *prepared, real u, real v, uint64_t *rays);

/* Chapter 03's renderer: the knob (its row in *row, aimed at *test, which
 * the caller owns), the built-in scene and the functions above. */
renderer triangle_stage_renderer(int *test, knob *row);

#endif
