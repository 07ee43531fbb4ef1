/* shading_stage.h - chapter 05: the renderer that chapters 05-11 share: a render.c fills a
 * shading_stage and calls shading_main() (README, "One renderer for every shading chapter"). */
#ifndef CH05_RENDERER_SHADING_STAGE_H
#define CH05_RENDERER_SHADING_STAGE_H

#include "01_camera_rays/camera.h"
#include "04_many_shapes/renderer/shape_knobs.h"
#include "05_lambert/tracer.h"

/* The closest-hit query of a prepared scene, and what it owns (freed by release unless NULL). */
typedef struct {
    closest_hit_fn closest_hit;
    const void *accel;
    void *owned;
    void (*release)(void *owned);
} hit_query;

/* Builds the query over the scene's surface list (which outlives it) with the knobs the stage gives it:
 * 0, or -1 with "path: problem" in err. */
typedef int (*build_query_fn)(const void *knobs, const surface_list *list, const scene *desc, hit_query *q,
                              char *err, size_t err_size);

/* snippet: shading_stage */
typedef struct {
    const char *name;    /* "05_lambert": the default output is name.png */
    const char *summary; /* first line of --help */
    const knob *knobs;   /* the stage's own knobs, listed after --sphere and --triangle */
    int n_knobs;
    unsigned modelled;   /* the scene_features the stage models */
    shade_fn shade;
    stage_knobs shade_knobs; /* becomes tracer.knobs: where the knobs' rows are aimed */
    shape_knobs shapes;      /* --sphere and --triangle: shading_main aims their rows here */
    build_query_fn build_query; /* NULL: chapter 04's linear scan (closest_hit_linear) */
    const void *query_knobs;    /* build_query's knobs, of the type it takes (NULL: none) */
    int (*builtin)(scene *desc); /* NULL: the shared built-in scene (shading_scene.h) */
    bool accelerated;            /* build_query makes an acceleration structure (chapter 11) */
} shading_stage;
/* end snippet */
#define MAX_STAGE_KNOBS 14 /* the most knobs a stage may have */

/* The renderer's main(): options, scene, render, PNG, summary (renderer.h). */
int shading_main(const shading_stage *stage, int argc, char **argv);

/* What a shading renderer traces for one scene, prepared from desc (which must outlive it) with the
 * stage's shading, --sphere and --triangle: NULL with "path:line: problem" in err. */
typedef struct {
    camera cam;
    surface_list list;
    hit_query query;
    tracer tr;
} shading_view;
shading_view *shading_prepare(const shading_stage *stage, const scene *desc, sphere_formula formula,
                              triangle_test test, char *err, size_t err_size);
/* A sample_fn (render_loop.h): the eye ray through (u, v), counted as RAY_EYE. */
color shading_sample(const void *view, real u, real v, uint64_t *rays);
void shading_release(void *view);

#endif
