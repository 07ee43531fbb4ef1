/* grid_scene.c - chapter 11: the built-in scene, what grids are for and where they break. */
#include "11_grid/scenes/grid_scene.h"

#include <math.h>

#include "scene_build.h"

/* What grids are for, and where they break: a floor of two huge triangles
 * under a torus of 2304 small ones and a spiral of 1000 small spheres, one
 * big sphere among them, Lambertian (the torus in RGBNormals), lit by two
 * point lights and a little ambient light. */
int grid_scene(scene *desc)
{
    desc->has_camera = true;
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 4.5, 9},
        .view_dir = {0, -0.45, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 2,
        .view_width = 2,
        .view_height = 2,
    };
    desc->back_color = color_make((real)0.55, (real)0.7, (real)0.9);
    desc->ambient = color_make((real)0.04, (real)0.04, (real)0.05);
    /* A key light high on the left, a weaker fill light on the right. */
    if (scene_add_light(desc, (scene_light){.position = {-6, 10, 6}, .intensity = {150, 150, 150}}) < 0 ||
        scene_add_light(desc, (scene_light){.position = {7, 5, 4}, .intensity = {30, 30, 36}}) < 0)
        return -1;
    const color colors[] = {
        {0.45, 0.45, 0.4}, {0.8, 0.15, 0.1}, {0.1, 0.25, 0.8}, {0.15, 0.6, 0.2}, {0.95, 0.8, 0.1}, {0.6, 0.2, 0.7},
    };
    enum { N_COLORS = sizeof colors / sizeof colors[0] };
    int shader[N_COLORS + 1];
    for (int k = 0; k < N_COLORS; k++) {
        scene_shader s = scene_default_shader(SHADER_LAMBERTIAN);
        s.diffuse_color = colors[k];
        shader[k] = scene_add_shader(desc, s);
    }
    shader[N_COLORS] = scene_add_shader(desc, scene_default_shader(SHADER_RGB_NORMALS));
    for (int k = 0; k <= N_COLORS; k++)
        if (shader[k] < 0)
            return -1;

    /* The floor: two triangles 40 units wide, far beyond everything else. */
    const vec3 floor[4] = {{-20, 0, -20}, {20, 0, -20}, {20, 0, 20}, {-20, 0, 20}};
    if (scene_add_surface(desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = shader[0], .v0 = floor[0],
                                                .v1 = floor[2], .v2 = floor[1]}) < 0 ||
        scene_add_surface(desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = shader[0], .v0 = floor[0],
                                                .v1 = floor[3], .v2 = floor[2]}) < 0)
        return -1;
    /* A torus of radii 1.3 and 0.45 about the y axis, 48 x 24 quads. */
    const int nu = 48, nv = 24;
    const double R = 1.3, r = 0.45, pi = 3.14159265358979323846;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            vec3 q[4];
            for (int c = 0; c < 4; c++) {
                double u = 2 * pi * (i + (c == 1 || c == 2)) / nu, v = 2 * pi * (j + (c >= 2)) / nv;
                q[c] = vec3_make((real)((R + r * cos(v)) * cos(u)), (real)(1 + r * sin(v)),
                                 (real)((R + r * cos(v)) * sin(u)));
            }
            scene_surface t = {.kind = SURFACE_TRIANGLE, .shader = shader[N_COLORS]};
            t.v0 = q[0], t.v1 = q[2], t.v2 = q[1];
            if (scene_add_surface(desc, t) < 0)
                return -1;
            t.v0 = q[0], t.v1 = q[3], t.v2 = q[2];
            if (scene_add_surface(desc, t) < 0)
                return -1;
        }
    /* 1000 small spheres on a golden-angle spiral around it. */
    for (int k = 0; k < 1000; k++) {
        double a = k * 2.39996322972865332, rho = 2.2 + 3.2 * sqrt(k / 1000.0);
        scene_surface s = {.kind = SURFACE_SPHERE, .shader = shader[1 + k % (N_COLORS - 1)],
                           .center = {(real)(rho * cos(a)), (real)(0.12 + 0.004 * (k % 50)),
                                      (real)(rho * sin(a))},
                           .radius = (real)0.12};
        if (scene_add_surface(desc, s) < 0)
            return -1;
    }
    /* One big sphere behind the torus. */
    scene_surface big = {.kind = SURFACE_SPHERE, .shader = shader[2], .center = {0, 1.6, -4.5}, .radius = 1.6};
    return scene_add_surface(desc, big) < 0 ? -1 : 0;
}
