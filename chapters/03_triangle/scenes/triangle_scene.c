/* triangle_scene.c - chapter 03: the built-in scene. */
#include "03_triangle/scenes/triangle_scene.h"

#include "03_triangle/scenes/icosahedron.h"
#include "scene_build.h"

static int add_triangle(scene *desc, vec3 v0, vec3 v1, vec3 v2)
{
    scene_surface surface = {.kind = SURFACE_TRIANGLE, .shader = -1, .v0 = v0, .v1 = v1, .v2 = v2};
    return scene_add_surface(desc, surface);
}

int triangle_scene_add_icosahedron(scene *desc, vec3 centre, real radius)
{
    vec3 v[ICOSAHEDRON_VERTICES];
    triangle faces[ICOSAHEDRON_FACES];
    icosahedron_vertices(centre, radius, v);
    icosahedron_triangles(v, faces);
    for (int f = 0; f < ICOSAHEDRON_FACES; f++)
        if (add_triangle(desc, faces[f].a, faces[f].b, faces[f].c) < 0)
            return -1;
    return 0;
}

int triangle_scene(scene *desc)
{
    desc->has_camera = true;
    desc->back_color = color_make((real)0.01, (real)0.01, (real)0.015);
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 0, 6},
        .view_dir = {0, 0, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 1,
        .view_width = 1.2,
        .view_height = 0.9,
    };
    if (add_triangle(desc, vec3_make(-3, -1.6, 0), vec3_make(-0.2, -1.6, 0), vec3_make(-1.6, 1.8, 0)) < 0)
        return -1;
    return triangle_scene_add_icosahedron(desc, vec3_make(1.6, 0, -0.5), (real)1.4);
}
