/* render.c - chapter 02's renderer: the lecture's "Image so far".
 *
 * Eye rays from chapter 01's camera, one sphere intersection per sphere:
 * a pixel is white where its ray meets a sphere and the background colour
 * where it meets none.  Which sphere is nearest does not matter yet, every
 * sphere is the same white (chapter 04 adds the closest hit and colours).
 *   --sphere=robust    the robust formula (default);
 *   --sphere=textbook  the lecture's quadratic formula as printed;
 *   --sphere=compare   textbook on the left half of the image, robust on
 *                      the right: the figure of README.md.
 */
#include <stdlib.h>

#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "02_sphere/sphere.h"
#include "renderer.h"
#include "scene_build.h"

enum { FORMULA_ROBUST, FORMULA_TEXTBOOK, FORMULA_COMPARE };
static const char *const formula_choices[] = {"robust", "textbook", "compare", NULL};
static int formula = FORMULA_ROBUST;

static const knob knobs[] = {
    {"sphere", KNOB_CHOICE, &formula, formula_choices,
     "ray-sphere formula; compare: textbook on the left half, robust on the right"},
};

typedef struct {
    camera cam;
    sphere *spheres;
    int n_spheres;
    color background; /* <backColor> */
} stage;

/* snippet: trace */
static color sample(const void *scene, real u, real v, uint64_t *rays)
{
    const stage *st = scene;
    sphere_formula f = formula == FORMULA_TEXTBOOK || (formula == FORMULA_COMPARE && u < (real)0.5)
                           ? SPHERE_TEXTBOOK
                           : SPHERE_ROBUST;
    ray r = camera_ray(&st->cam, u, v);
    ++*rays;
    for (int k = 0; k < st->n_spheres; k++) {
        real t;
        vec3 n;
        if (sphere_intersect(&st->spheres[k], r, 0, REAL_INFINITY, f, &t, &n)) /* s.intersect(ray, 0, +inf) */
            return color_make(1, 1, 1);
    }
    return st->background;
}
/* end snippet */

/* The lecture's slide: Sphere((0.0, 0.0, 0.0), 1.0), seen from 4 units away. */
static int builtin(scene *desc)
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

static void release(void *prepared)
{
    stage *st = prepared;
    if (st)
        free(st->spheres);
    free(st);
}

static void *prepare(const scene *desc, char *err, size_t err_size)
{
    const char *where = scene_name(desc);
    stage *st = calloc(1, sizeof *st);
    if (st)
        st->spheres = malloc(((size_t)desc->n_surfaces + 1) * sizeof *st->spheres);
    if (!st || !st->spheres) {
        snprintf(err, err_size, "%s: out of memory", where);
        release(st);
        return NULL;
    }
    if (!camera_from_scene(&st->cam, desc, err, err_size)) {
        release(st);
        return NULL;
    }
    for (int k = 0; k < desc->n_surfaces; k++) /* other surfaces are named as ignored */
        if (desc->surfaces[k].kind == SURFACE_SPHERE)
            st->spheres[st->n_spheres++] = (sphere){desc->surfaces[k].center, desc->surfaces[k].radius};
    st->background = desc->back_color;
    return st;
}

int main(int argc, char **argv)
{
    const renderer r = {
        .name = "02_sphere",
        .summary = "02_sphere: white spheres on the background colour (the lecture's \"Image so far\")",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = FEATURE_SPHERES,
        .default_width = 512,
        .default_height = 512,
        .builtin = builtin,
        .prepare = prepare,
        .sample = sample,
        .pixel_to_image = pixel_to_image,
        .release = release,
    };
    return renderer_main(&r, argc, argv);
}
