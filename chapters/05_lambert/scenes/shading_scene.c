/* shading_scene.c - chapter 05: the built-in scene of the shading chapters. */
#include "05_lambert/scenes/shading_scene.h"

#include "04_many_shapes/scenes/shapes_scene.h"
#include "scene_build.h"

static int add_shader(scene *desc, shader_kind kind, color diffuse, color specular, real exponent)
{
    scene_shader s = scene_default_shader(kind);
    s.diffuse_color = diffuse;
    s.specular_color = specular;
    s.exponent = exponent;
    return scene_add_shader(desc, s);
}

int shading_scene(scene *desc)
{
    shapes_view(desc); /* chapter 04's camera on chapter 04's layout */
    desc->back_color = color_make((real)0.02, (real)0.03, (real)0.05);
    desc->ambient = color_make((real)0.01, (real)0.01, (real)0.012);
    desc->exposure = (real)1.6;
    const color none = {0, 0, 0};
    int shader[6] = {
        /* diffuseColor is k_d = R / pi: a reflectance R <= 1 gives k_d <= 1/pi ~ 0.32 */
        add_shader(desc, SHADER_LAMBERTIAN, color_make(0.25, 0.25, 0.22), none, 1),    /* floor */
        add_shader(desc, SHADER_PHONG, color_make(0.25, 0.04, 0.03), color_make(0.6, 0.6, 0.6), 60), /* red */
        add_shader(desc, SHADER_LAMBERTIAN, color_make(0.03, 0.08, 0.25), none, 1),    /* blue, matte */
        add_shader(desc, SHADER_PHONG, color_make(0.05, 0.18, 0.06), color_make(0.3, 0.3, 0.3), 12), /* green */
        add_shader(desc, SHADER_LAMBERTIAN, color_make(0.3, 0.25, 0.03), none, 1),     /* yellow */
        add_shader(desc, SHADER_PHONG, color_make(0.25, 0.25, 0.25), color_make(1, 1, 1), 300), /* white */
    };
    for (int k = 0; k < 6; k++)
        if (shader[k] < 0)
            return -1;
    if (shapes_add_solids(desc, shader) < 0) /* chapter 04's floor, spheres and box */
        return -1;
    const scene_surface surfaces[] = { /* the triangle leans back, the small sphere floats */
        {.kind = SURFACE_TRIANGLE, .shader = shader[4], .v0 = {-2.3, 0, -1.2}, .v1 = {0.1, 0, -1.2},
         .v2 = {-1.1, 2.4, -2.4}},
        {.kind = SURFACE_SPHERE, .shader = shader[5], .center = {-0.2, 0.9, 1.6}, .radius = 0.3},
    };
    for (size_t k = 0; k < sizeof surfaces / sizeof surfaces[0]; k++)
        if (scene_add_surface(desc, surfaces[k]) < 0)
            return -1;
    /* The key light high on the left, a weaker fill light low on the right. */
    if (scene_add_light(desc, (scene_light){.position = {-4, 7, 1}, .intensity = {70, 70, 70}}) < 0 ||
        scene_add_light(desc, (scene_light){.position = {5, 2.5, 3}, .intensity = {15, 15, 18}}) < 0)
        return -1;
    return 0;
}
