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
#include "01_camera_rays/pixel.h"
#include "04_many_shapes/flat_shading.h"
#include "04_many_shapes/shape_knobs.h"
#include "04_many_shapes/scenes/shapes_scene.h"
#include "04_many_shapes/shapes_stage.h"
#include "renderer.h"

static color sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const shapes_stage *st = prepared;
    ++*rays;
    /* Eye rays start at the eye: every hit with t > 0 is in front of it. */
    return trace_flat(&st->list, st->desc, camera_ray(&st->cam, u, v), 0, REAL_INFINITY);
}

int main(int argc, char **argv)
{
    shape_knobs knobs = SHAPE_KNOBS_DEFAULT;
    knob rows[SHAPE_KNOBS];
    shape_knob_rows(&knobs, rows);
    const renderer r = {
        .name = "04_many_shapes",
        .summary = "04_many_shapes: every surface of the scene, the closest hit, one flat colour per surface",
        .knobs = rows,
        .n_knobs = SHAPE_KNOBS,
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS,
        .default_width = 512,
        .default_height = 512,
        .builtin = shapes_scene,
        .prepare = shapes_stage_prepare,
        .context = &knobs,
        .sample = sample,
        .release = shapes_stage_release,
        .pixel_to_image = pixel_to_image,
    };
    return renderer_main(&r, argc, argv);
}
