/* shading_stage.c - chapter 05: the renderer that every shading chapter shares. */
#include "05_lambert/renderer/shading_stage.h"

#include <stdio.h>
#include <stdlib.h>

#include "01_camera_rays/pixel.h"
#include "05_lambert/scenes/shading_scene.h"
#include "joined_knobs.h"

void shading_release(void *prepared)
{
    shading_view *view = prepared;
    if (!view)
        return;
    if (view->query.release)
        view->query.release(view->query.owned);
    surface_list_free(&view->list);
    free(view);
}

shading_view *shading_prepare(const shading_stage *stage, const scene *desc, sphere_formula formula,
                              triangle_test test, char *err, size_t err_size)
{
    shading_view *view = calloc(1, sizeof *view);
    if (!view) {
        snprintf(err, err_size, "%s: out of memory", scene_name(desc));
        return NULL;
    }
    surface_list_init(&view->list, formula, test);
    view->query = (hit_query){.closest_hit = closest_hit_linear, .accel = &view->list}; /* or the stage's own */
    build_query_fn build = stage->build_query;
    if (!camera_from_scene(&view->cam, desc, err, err_size) ||
        surface_list_from_scene(&view->list, desc, err, err_size) != 0 ||
        (build && build(stage->query_knobs, &view->list, desc, &view->query, err, err_size) != 0)) {
        shading_release(view);
        return NULL;
    }
    view->tr = (tracer){
        .closest_hit = view->query.closest_hit,
        .accel = view->query.accel,
        .desc = desc,
        .shade = stage->shade,
        .knobs = stage->shade_knobs,
        .weight = {1, 1, 1}, /* eye rays */
    };
    return view;
}

color shading_sample(const void *view, real u, real v, uint64_t *rays)
{
    const shading_view *sv = view;
    ++rays[RAY_EYE]; /* it starts at the eye: every hit with t > 0 is in front of it */
    return trace(&sv->tr, camera_ray(&sv->cam, u, v), 0, REAL_INFINITY, 0, rays);
}

/* renderer.h's prepare: its context is the stage, with the values of every knob. */
static void *prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    const shading_stage *stage = context;
    return shading_prepare(stage, desc, (sphere_formula)stage->shapes.sphere, (triangle_test)stage->shapes.triangle,
                           err, err_size);
}

int shading_main(const shading_stage *stage, int argc, char **argv)
{
    shading_stage st = *stage;
    st.shapes = (shape_knobs)SHAPE_KNOBS_DEFAULT;
    knob shapes[SHAPE_KNOBS];
    shape_knob_rows(&st.shapes, shapes);
    const renderer r = {
        .name = stage->name,
        .summary = stage->summary,
        .knobs = stage->knobs,
        .n_knobs = stage->n_knobs,
        .modelled = stage->modelled,
        .accelerated = stage->accelerated,
        .default_width = 512,
        .default_height = 512,
        .builtin = stage->builtin ? stage->builtin : shading_scene,
        .prepare = prepare,
        .context = &st,
        .sample = shading_sample,
        .release = shading_release,
        .pixel_to_image = pixel_to_image, /* chapter 01's: the student's own mapping */
    };
    return renderer_main_joined(&r, shapes, SHAPE_KNOBS, argc, argv); /* --sphere and --triangle first */
}
