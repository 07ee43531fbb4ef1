/* shapes_scene.c - chapter 04: the built-in scene, overlapping shapes in flat colours. */
#include "04_many_shapes/scenes/shapes_scene.h"

#include "scene_build.h"

void shapes_view(scene *desc)
{
    desc->has_camera = true;
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 2.2, 6.5},
        .view_dir = {0, -0.3, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 2,
        .view_width = 2,
        .view_height = 2,
    };
}

int shapes_add_solids(scene *desc, const int shader[4])
{
    const scene_surface solids[] = {
        {.kind = SURFACE_BOX, .shader = shader[0], .min_pt = {-5, -0.2, -5}, .max_pt = {5, 0, 5}},
        {.kind = SURFACE_SPHERE, .shader = shader[1], .center = {-0.7, 0.9, -0.3}, .radius = 0.9},
        {.kind = SURFACE_SPHERE, .shader = shader[2], .center = {0.5, 0.6, 0.4}, .radius = 0.6},
        {.kind = SURFACE_BOX, .shader = shader[3], .min_pt = {0.75, 0, -0.7}, .max_pt = {1.95, 1.1, 0.8}},
    };
    for (size_t k = 0; k < sizeof solids / sizeof solids[0]; k++)
        if (scene_add_surface(desc, solids[k]) < 0)
            return -1;
    return 0;
}

/* Overlapping shapes, each its own flat colour: a floor slab, two spheres
 * that cut into each other, a box pushed into the blue sphere, a triangle
 * standing through the red sphere, and a small RGBNormals sphere. */
int shapes_scene(scene *desc)
{
    shapes_view(desc);
    desc->back_color = color_make((real)0.55, (real)0.7, (real)0.9);
    const color colors[] = {
        {0.45, 0.45, 0.4}, /* floor */
        {0.8, 0.15, 0.1},  /* red sphere */
        {0.1, 0.25, 0.8},  /* blue sphere */
        {0.15, 0.6, 0.2},  /* green box */
        {0.95, 0.8, 0.1},  /* yellow triangle */
    };
    int shader[6];
    for (int k = 0; k < 5; k++) {
        scene_shader s = scene_default_shader(SHADER_LAMBERTIAN);
        s.diffuse_color = colors[k];
        shader[k] = scene_add_shader(desc, s);
    }
    shader[5] = scene_add_shader(desc, scene_default_shader(SHADER_RGB_NORMALS));
    for (int k = 0; k < 6; k++)
        if (shader[k] < 0)
            return -1;

    if (shapes_add_solids(desc, shader) < 0)
        return -1;
    const scene_surface surfaces[] = {
        {.kind = SURFACE_TRIANGLE, .shader = shader[4], .v0 = {-2.3, 0, -1.2}, .v1 = {0.1, 0, -1.2},
         .v2 = {-1.1, 2.4, 0.9}},
        {.kind = SURFACE_SPHERE, .shader = shader[5], .center = {-0.3, 0.35, 1.3}, .radius = 0.35},
    };
    for (size_t k = 0; k < sizeof surfaces / sizeof surfaces[0]; k++)
        if (scene_add_surface(desc, surfaces[k]) < 0)
            return -1;
    return 0;
}
