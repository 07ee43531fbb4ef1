/* render.c - chapter 04's renderer: every surface, the closest hit, flat colours (README). */
#include <stdio.h>
#include <stdlib.h>
#include "01_camera_rays/pixel.h"
#include "04_many_shapes/flat_shading.h"
#include "04_many_shapes/renderer/shape_knobs.h"
#include "04_many_shapes/scenes/shapes_scene.h"
#include "renderer.h"

typedef struct {
    camera cam;
    surface_list list;
    const scene *desc; /* its shaders and backColor give the colours */
} shapes;

static void release(void *prepared) /* never NULL: renderer_main releases only what was prepared */
{
    shapes *st = prepared;
    surface_list_free(&st->list);
    free(st);
}

static void *prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    const shape_knobs *knobs = context; /* --sphere and --triangle, owned by main */
    shapes *st = calloc(1, sizeof *st);
    if (!st) {
        snprintf(err, err_size, "%s: out of memory", scene_name(desc));
        return NULL;
    }
    st->desc = desc;
    surface_list_init(&st->list, (sphere_formula)knobs->sphere, (triangle_test)knobs->triangle);
    if (camera_from_scene(&st->cam, desc, err, err_size) && !surface_list_from_scene(&st->list, desc, err, err_size))
        return st;
    release(st);
    return NULL;
}

static color sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const shapes *st = prepared;
    ++*rays; /* an eye ray starts at the eye: every hit with t > 0 is in front of it */
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
        .knobs = rows, .n_knobs = SHAPE_KNOBS, .builtin = shapes_scene, .default_width = 512, .default_height = 512,
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS,
        .prepare = prepare, .context = &knobs, .sample = sample, .release = release, .pixel_to_image = pixel_to_image,
    };
    return renderer_main(&r, argc, argv);
}
