/* tracer.h - chapter 05: the lecture's Scene.trace over any closest-hit query, and what a shade
 * function is given; every shading stage (05-11) traces with it (README, "Shading a hit"). */
#ifndef CH05_TRACER_H
#define CH05_TRACER_H

#include <stdint.h>

#include "04_many_shapes/surface.h"
#include "color.h"
#include "render_loop.h"

/* snippet: closest_hit_fn */
/* "What does this ray hit first?": the hit with the smallest t in (t_min, t_max) in `accel`, or false.
 * Chapter 04's linear scan (closest_hit_linear: accel is a surface_list) and chapter 11's grid fit it. */
typedef bool (*closest_hit_fn)(const void *accel, ray r, real t_min, real t_max, hit_record *hit);
/* end snippet */
bool closest_hit_linear(const void *accel, ray r, real t_min, real t_max, hit_record *hit);

/* snippet: shading_point */
/* What a shade function is given: the lecture's (ray, point, normal). */
typedef struct {
    ray r;          /* the ray that found the point */
    hit_record hit; /* its GEOMETRIC unit normal, not turned: sidedness, where secondary rays start */
    vec3 n;         /* the SHADING normal: unit, n . v >= 0 (interpolated from chapter 10 on) */
    vec3 v;         /* unit, towards the viewer: -normalize(d) */
    const scene_shader *shader; /* looked up once by trace() (chapter 10: a copy with the texture's k_d) */
} shading_point;
/* end snippet */

typedef struct tracer tracer;

/* The stage's shading: the radiance leaving sp's point towards the viewer; depth: the bounces that
 * led here (0 for an eye ray); every ray it casts is added to the counters `rays` (render_loop.h). */
typedef color (*shade_fn)(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays);

/* The knobs of the stages from 06 on, each its chapter's struct (NULL: the stage's defaults). */
typedef struct {
    const struct spawn_knobs *spawn;   /* 06: --shadow-eps */
    const struct phong_knobs *phong;   /* 07: --phong */
    const struct path_knobs *path;     /* 08: --depth, --min-weight */
    const struct glass_knobs *glass;   /* 09: --fresnel */
    const struct interp_knobs *interp; /* 10: --normals, --texture-filter, --below-surface */
} stage_knobs;

/* snippet: tracer */
struct tracer {
    closest_hit_fn closest_hit; /* the "what does this ray hit first?" query ... */
    const void *accel;          /* ... and what it searches (a surface_list, a grid) */
    const scene *desc;          /* shaders, lights, backColor, ambient */
    shade_fn shade;             /* the stage's shading */
    stage_knobs knobs;          /* the values of the stages' knobs (none for chapter 05) */
    color weight;               /* the product of the coefficients along the path (chapter 08); 1 for eye rays */
};
/* end snippet */

/* The closest hit of r in (t_min, t_max) shaded by tr->shade, or the backColor when r hits nothing.
 * r is not counted: its caller counts it by its kind. */
color trace(const tracer *tr, ray r, real t_min, real t_max, int depth, uint64_t *rays);

/* The shading normal of a geometric unit normal n seen along d: n when n . d < 0, else -n. */
vec3 normal_towards_viewer(vec3 n, vec3 d);

#endif
