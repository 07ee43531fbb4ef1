/* shapes_stage.c - chapter 04: what its renderer traces. */
#include "04_many_shapes/shapes_stage.h"

#include <stdio.h>
#include <stdlib.h>

#include "04_many_shapes/scene_surfaces.h"
#include "04_many_shapes/shape_knobs.h"

void shapes_stage_release(void *prepared)
{
    shapes_stage *st = prepared;
    if (st)
        surface_list_free(&st->list);
    free(st);
}

void *shapes_stage_prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    const shape_knobs *knobs = context; /* owned by main */
    shapes_stage *st = malloc(sizeof *st);
    if (!st) {
        snprintf(err, err_size, "%s: out of memory", scene_name(desc));
        return NULL;
    }
    st->desc = desc;
    surface_list_init(&st->list, chosen_sphere_formula(knobs), chosen_triangle_test(knobs));
    if (!camera_from_scene(&st->cam, desc, err, err_size)) {
        shapes_stage_release(st);
        return NULL;
    }
    if (surface_list_from_scene(&st->list, desc, err, err_size) != 0) {
        shapes_stage_release(st);
        return NULL;
    }
    return st;
}
