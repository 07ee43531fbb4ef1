/* render.c - chapter 04's renderer: every surface, closest hit, flat colours.
 *
 * Each pixel's eye ray (chapter 01) is tested against the whole surface list
 * (closest_hit.h) and coloured by the first surface it hits: the shader's
 * diffuseColor, (n + 1) / 2 for RGBNormals, the backColor for a miss.  No
 * lights yet, so shapes are flat silhouettes; where two shapes overlap, the
 * closer one hides the other, and where they cut through each other the
 * outline of the cut shows.
 *
 * Knobs: --sphere=robust|textbook (chapter 02), --triangle=watertight|cramer
 * (chapter 03; watertight by default, TRIANGLE_TEST_DEFAULT), passed to every
 * intersection through the surface list.
 */
#include <stdlib.h>

#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "04_many_shapes/flat_shading.h"
#include "04_many_shapes/scene_surfaces.h"
#include "renderer.h"
#include "scene_build.h"

static const char *const sphere_choices[] = {"robust", "textbook", NULL};
static const sphere_formula sphere_formulas[] = {SPHERE_ROBUST, SPHERE_TEXTBOOK};
static int sphere_choice = 0;
static const char *const triangle_choices[] = {"cramer", "watertight", NULL};
static const triangle_test triangle_tests[] = {TRIANGLE_CRAMER, TRIANGLE_WATERTIGHT};
static int triangle_choice = TRIANGLE_TEST_DEFAULT; /* triangle_choices is in the order of the enum */

static const knob knobs[] = {
    {"sphere", KNOB_CHOICE, &sphere_choice, sphere_choices, "ray-sphere formula (chapter 02)"},
    {"triangle", KNOB_CHOICE, &triangle_choice, triangle_choices, "ray-triangle test (chapter 03)"},
};

/* What the stage traces: the camera, the surface list, and the scene
 * description, whose shaders and backColor give the colours. */
typedef struct {
    camera cam;
    surface_list list;
    const scene *desc;
} stage;

static color sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const stage *st = prepared;
    ++*rays;
    /* Eye rays start at the eye: every hit with t > 0 is in front of it. */
    return trace_flat(&st->list, st->desc, camera_ray(&st->cam, u, v), 0, REAL_INFINITY);
}

static void release(void *prepared)
{
    stage *st = prepared;
    if (st)
        surface_list_free(&st->list);
    free(st);
}

static void *prepare(const scene *desc, char *err, size_t err_size)
{
    stage *st = malloc(sizeof *st);
    if (!st) {
        snprintf(err, err_size, "%s: out of memory", desc->path ? desc->path : "built-in scene");
        return NULL;
    }
    st->desc = desc;
    surface_list_init(&st->list, sphere_formulas[sphere_choice], triangle_tests[triangle_choice]);
    if (!camera_from_scene(&st->cam, desc, err, err_size)) {
        release(st);
        return NULL;
    }
    if (surface_list_from_scene(&st->list, desc, err, err_size) != 0) {
        release(st);
        return NULL;
    }
    return st;
}

/* snippet: builtin */
/* Overlapping shapes, each its own flat colour: a floor slab, two spheres
 * that cut into each other, a box pushed into the blue sphere, a triangle
 * standing through the red sphere, and a small RGBNormals sphere. */
static int builtin(scene *desc)
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

    const scene_surface surfaces[] = {
        {.kind = SURFACE_BOX, .shader = shader[0], .min_pt = {-5, -0.2, -5}, .max_pt = {5, 0, 5}},
        {.kind = SURFACE_SPHERE, .shader = shader[1], .center = {-0.7, 0.9, -0.3}, .radius = 0.9},
        {.kind = SURFACE_SPHERE, .shader = shader[2], .center = {0.5, 0.6, 0.4}, .radius = 0.6},
        {.kind = SURFACE_BOX, .shader = shader[3], .min_pt = {0.75, 0, -0.7}, .max_pt = {1.95, 1.1, 0.8}},
        {.kind = SURFACE_TRIANGLE, .shader = shader[4], .v0 = {-2.3, 0, -1.2}, .v1 = {0.1, 0, -1.2},
         .v2 = {-1.1, 2.4, 0.9}},
        {.kind = SURFACE_SPHERE, .shader = shader[5], .center = {-0.3, 0.35, 1.3}, .radius = 0.35},
    };
    for (size_t k = 0; k < sizeof surfaces / sizeof surfaces[0]; k++)
        if (scene_add_surface(desc, surfaces[k]) < 0)
            return -1;
    return 0;
}
/* end snippet */

int main(int argc, char **argv)
{
    const renderer r = {
        .name = "04_many_shapes",
        .summary = "04_many_shapes: every surface of the scene, the closest hit, one flat colour per surface",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS,
        .default_width = 512,
        .default_height = 512,
        .builtin = builtin,
        .prepare = prepare,
        .sample = sample,
        .release = release,
        .pixel_to_image = pixel_to_image,
    };
    return renderer_main(&r, argc, argv);
}
