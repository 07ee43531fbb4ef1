/* glass_scene.c - chapter 09: the built-in scene of the refraction stage. */
#include "09_refraction/scenes/glass_scene.h"

#include "scene_build.h"

static int add_shader(scene *desc, shader_kind kind, color diffuse, color mirror)
{
    scene_shader s = scene_default_shader(kind);
    s.diffuse_color = diffuse;
    s.mirror_coefficient = mirror;
    return scene_add_shader(desc, s);
}

/* The square of the floor with corner (x, 0, z) as two triangles wound
 * counter-clockwise seen from above (normal +y). */
static int add_tile(scene *desc, int shader, real x, real z)
{
    const real s = GLASS_SCENE_TILE;
    vec3 a = {x, 0, z}, b = {x, 0, z + s}, c = {x + s, 0, z + s}, d = {x + s, 0, z};
    scene_surface tri = {.kind = SURFACE_TRIANGLE, .shader = shader, .v0 = a, .v1 = b, .v2 = c};
    if (scene_add_surface(desc, tri) < 0)
        return -1;
    tri.v1 = c;
    tri.v2 = d;
    return scene_add_surface(desc, tri);
}

int glass_scene(scene *desc)
{
    desc->has_camera = true;
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0.4, 2.6, 6.2},
        .view_dir = {-0.05, -0.32, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 2,
        .view_width = 1.6,
        .view_height = 1.6,
    };
    desc->back_color = color_make((real)0.25, (real)0.3, (real)0.4);
    desc->ambient = color_make((real)0.02, (real)0.02, (real)0.02);
    const color none = {0, 0, 0};
    int light_tile = add_shader(desc, SHADER_LAMBERTIAN, color_make(0.3, 0.29, 0.26), none);
    int dark_tile = add_shader(desc, SHADER_LAMBERTIAN, color_make(0.04, 0.05, 0.08), none);
    int red = add_shader(desc, SHADER_PHONG, color_make(0.28, 0.03, 0.03), none);
    int blue = add_shader(desc, SHADER_LAMBERTIAN, color_make(0.03, 0.07, 0.3), none);
    int yellow = add_shader(desc, SHADER_LAMBERTIAN, color_make(0.3, 0.24, 0.02), none);
    int mirror = add_shader(desc, SHADER_LAMBERTIAN, color_make(0.01, 0.01, 0.01), color_make(0.85, 0.85, 0.85));
    int glass = add_shader(desc, SHADER_GLASS, none, none); /* refractiveIndex 1.5, the default */
    if (light_tile < 0 || dark_tile < 0 || red < 0 || blue < 0 || yellow < 0 || mirror < 0 || glass < 0)
        return -1;
    desc->shaders[red].specular_color = color_make(0.5, 0.5, 0.5);
    desc->shaders[red].exponent = 50;
    const int half = GLASS_SCENE_TILES / 2;
    for (int i = -half; i < half; i++)
        for (int k = -half; k < half; k++)
            if (add_tile(desc, (i + k) % 2 == 0 ? light_tile : dark_tile, i * GLASS_SCENE_TILE,
                         k * GLASS_SCENE_TILE) < 0)
                return -1;
    const scene_surface surfaces[] = {
        {.kind = SURFACE_SPHERE, .shader = glass, .center = {0, 1, 0.6}, .radius = 1},
        {.kind = SURFACE_SPHERE, .shader = red, .center = {-1.6, 0.8, -2.2}, .radius = 0.8},
        {.kind = SURFACE_BOX, .shader = blue, .min_pt = {0.5, 0, -3.2}, .max_pt = {1.7, 1.6, -2.0}},
        {.kind = SURFACE_TRIANGLE, .shader = yellow, .v0 = {-0.6, 0, -4}, .v1 = {0.6, 0, -4}, .v2 = {0, 2.2, -4.4}},
        {.kind = SURFACE_SPHERE, .shader = mirror, .center = {2.1, 0.6, 0.2}, .radius = 0.6},
    };
    for (size_t k = 0; k < sizeof surfaces / sizeof surfaces[0]; k++)
        if (scene_add_surface(desc, surfaces[k]) < 0)
            return -1;
    if (scene_add_light(desc, (scene_light){.position = {-5, 8, -3}, .intensity = {90, 90, 90}}) < 0 ||
        scene_add_light(desc, (scene_light){.position = {4, 3, 5}, .intensity = {12, 12, 14}}) < 0)
        return -1;
    return 0;
}
