/* explain.h - the tree of rays behind one pixel (--explain X,Y).
 *
 * The renderer renders as usual, then computes the explained pixel once more
 * through render_pixel (render_loop.h), with a recorder switched on for this
 * thread.  The code that renders reports each step to it: the pixel's
 * samples, the eye ray (chapter 01's camera_ray), each surface tested and
 * its t or why it missed (chapters 02-04), the closest hit and the shading
 * terms (05-07), the shadow rays with their offset (06), the child rays with
 * depth, weight, eta, the cosines and Fresnel's R (08-09), the interpolated
 * attributes and the texel (10), the grid's cells (11).  Nothing is computed
 * twice for the pixel's value: the explanation ends with the value
 * render_pixel returned, before and after display_encode, and the byte the
 * image holds there.
 *
 * When not explaining, explain_now is NULL and each report costs the one
 * branch of EXPLAIN().  Values the lecture names that the code keeps inside
 * an exercise (r^2, l, n . l, h, n . h) are shown from the inputs the given
 * code passed on; every term that adds up to the pixel is the code's own.
 */
#ifndef RT_EXPLAIN_H
#define RT_EXPLAIN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "color.h"
#include "image.h"
#include "options.h"
#include "ray.h"
#include "render_loop.h"
#include "scene.h"

typedef struct explainer explainer;

/* This thread's recorder; NULL when nothing is explained. */
extern _Thread_local explainer *explain_now;

/* A report: made only while explaining. */
#define EXPLAIN(call)        \
    do {                     \
        if (explain_now) {   \
            call;            \
        }                    \
    } while (0)

/* ---- reports (each called through EXPLAIN) ---- */

/* render_pixel: sample k of n at (du, dv) in the pixel, image position (u, v), and its radiance. */
void explain_sample(int k, int n, real du, real dv, real u, real v);
void explain_sample_done(color L);
/* Chapter 01: the eye ray of the current sample. */
void explain_eye_ray(ray r);
/* Chapter 04: the surface the next test is of (its index in the list, the scene surface and piece). */
void explain_surface(int index, int source, int face);
/* Chapter 02: a sphere test: roots (t0, t1) when the quadratic has any, and the hit t when one is in the window. */
void explain_sphere(vec3 c, real R, bool has_roots, real t0, real t1, real t_min, real t_max, bool hit, real t);
/* Chapter 03: a triangle test: a hit at (t, beta, gamma), or a miss whose line meets the triangle at t_line
 * (outside the window) or, when !line_hits, passes outside it or runs parallel to it. */
void explain_triangle(bool hit, real t, real beta, real gamma, real t_min, real t_max, bool line_hits, real t_line);
/* Chapters 03-04: the closest hit of the current ray (the index of its surface, its t and point). */
void explain_closest(int surface, int source, real t, vec3 point);
/* Chapter 05: trace() of a ray at `depth` over (t_min, t_max), with the path's weight; rays[] tells its kind. */
void explain_trace(ray r, real t_min, real t_max, int depth, color weight, const uint64_t *rays);
/* The ray found nothing: the background. */
void explain_miss(color background);
/* The point to shade: geometric normal n_g, shading normal n, v, and the shader's kind. */
void explain_shading(vec3 n_g, vec3 n, vec3 v, const scene_shader *shader);
/* The radiance trace() returns for the current ray. */
void explain_radiance(color L);
/* Chapters 05-07: one light's terms at point x: Lambert's, and the specular term when `specular`. */
void explain_light(const scene_light *light, vec3 x, vec3 n, vec3 v, color lambert, bool specular, color spec);
/* Chapter 07: the ambient term. */
void explain_ambient(color L_a);
/* Chapter 06: a ray leaves the surface at x from `origin` by `policy` (spawn_ray). */
void explain_spawn(const char *policy, vec3 x, vec3 origin, vec3 n_g);
/* Chapter 06: the shadow ray towards `target`, over (0, t_max) (spawn_ray_to). */
void explain_shadow_ray(ray r, real t_max, vec3 target);
/* Chapter 08: no deeper ray: the depth is exhausted, or the path's weight is too small. */
void explain_path_stop(bool depth_exhausted, int depth, real weight, real min_weight);
/* Chapter 09: what a glass surface does to the ray. */
void explain_glass(real eta_i, real eta_t, real cos_i, bool transmits, real cos_t, real R);
/* Chapter 10: at a point of scene surface `source`, the barycentrics (a mesh face's), the shading normal
 * (interpolated when smooth) and (u, v) (when has_uv). */
void explain_interp(int source, real beta, real gamma, bool smooth, vec3 n_s, bool has_uv, real u, real v);
/* Chapter 10: the texel colour read at (u, v) with `filter`. */
void explain_texel(real u, real v, const char *filter, color k_d);
/* Chapter 11: the grid's cell (i, j, k) is visited; it lists `surfaces` surfaces. */
void explain_cell(int i, int j, int k, long surfaces);

/* ---- the explanation of one pixel (renderer.c) ---- */

/* Computes pixel opt->explain_x, opt->explain_y (column from the left, row
 * from the top, as in the PNG) of the rendered img again with the recorder
 * on, prints its tree to `out`, writes opt->explain_json and
 * opt->explain_picture when given.  Returns 0, or -1 with "path: problem" in
 * err (nothing half-written). */
int explain_pixel(sample_fn sample, const void *prepared, const render_options *opt,
                  pixel_map_fn map, const image *img, const scene *desc, FILE *out, char *err, size_t err_size);

#endif
