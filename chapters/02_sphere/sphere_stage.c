/* sphere_stage.c - chapter 02: what its renderer traces, and the built-in scene. */
#include "02_sphere/sphere_stage.h"

#include <stdio.h>
#include <stdlib.h>

#include "scene_build.h"

int sphere_stage_scene(scene *desc)
{
    desc->has_camera = true;
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 0, 4},
        .view_dir = {0, 0, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 1,
        .view_width = 1,
        .view_height = 1,
    };
    scene_surface unit_sphere = {.kind = SURFACE_SPHERE, .shader = -1, .center = {0, 0, 0}, .radius = 1};
    return scene_add_surface(desc, unit_sphere) < 0 ? -1 : 0;
}

void sphere_stage_release(void *prepared)
{
    sphere_stage *st = prepared;
    if (st)
        free(st->spheres);
    free(st);
}

void *sphere_stage_prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    sphere_stage *st = calloc(1, sizeof *st);
    if (st)
        st->spheres = malloc(((size_t)desc->n_surfaces + 1) * sizeof *st->spheres);
    if (!st || !st->spheres) {
        snprintf(err, err_size, "%s: out of memory", scene_name(desc));
        sphere_stage_release(st);
        return NULL;
    }
    if (!camera_from_scene(&st->cam, desc, err, err_size)) {
        sphere_stage_release(st);
        return NULL;
    }
    for (int k = 0; k < desc->n_surfaces; k++) /* other surfaces are named as ignored */
        if (desc->surfaces[k].kind == SURFACE_SPHERE)
            st->spheres[st->n_spheres++] = (sphere){desc->surfaces[k].center, desc->surfaces[k].radius};
    st->background = desc->back_color;
    st->formula = *(const int *)context;
    return st;
}
