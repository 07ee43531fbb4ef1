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
 * intersection through the surface list (shape_knobs.h).  The built-in scene
 * is shapes_scene.h's.
 */
#include <stdlib.h>

#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "04_many_shapes/flat_shading.h"
#include "04_many_shapes/scene_surfaces.h"
#include "04_many_shapes/shape_knobs.h"
#include "04_many_shapes/shapes_scene.h"
#include "renderer.h"

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
        snprintf(err, err_size, "%s: out of memory", scene_name(desc));
        return NULL;
    }
    st->desc = desc;
    surface_list_init(&st->list, chosen_sphere_formula(), chosen_triangle_test());
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

int main(int argc, char **argv)
{
    const renderer r = {
        .name = "04_many_shapes",
        .summary = "04_many_shapes: every surface of the scene, the closest hit, one flat colour per surface",
        .knobs = shape_knobs,
        .n_knobs = SHAPE_KNOBS,
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS,
        .default_width = 512,
        .default_height = 512,
        .builtin = shapes_scene,
        .prepare = prepare,
        .sample = sample,
        .release = release,
        .pixel_to_image = pixel_to_image,
    };
    return renderer_main(&r, argc, argv);
}
