/* render.c - chapter 02's renderer: the lecture's "Image so far".
 *
 * Eye rays from chapter 01's camera, one sphere intersection per sphere:
 * a pixel is white where its ray meets a sphere and the background colour
 * where it meets none.  Which sphere is nearest does not matter yet, every
 * sphere is the same white (chapter 04 adds the closest hit and colours).
 *   --sphere=robust    the robust formula (default);
 *   --sphere=textbook  the lecture's quadratic formula as printed;
 *   --sphere=compare   textbook on the left half, robust on the right.
 */
#include "01_camera_rays/pixel.h"
#include "02_sphere/sphere_stage.h"
#include "renderer.h"

enum { FORMULA_ROBUST, FORMULA_TEXTBOOK, FORMULA_COMPARE };
static const char *const formula_choices[] = {"robust", "textbook", "compare", NULL};
static color sample(const void *scene, real u, real v, uint64_t *rays)
{
    const sphere_stage *st = scene;
    sphere_formula f = st->formula == FORMULA_TEXTBOOK || (st->formula == FORMULA_COMPARE && u < (real)0.5)
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

int main(int argc, char **argv)
{
    int formula = FORMULA_ROBUST;
    const knob knobs[] = {{"sphere", KNOB_CHOICE, &formula, formula_choices,
                           "ray-sphere formula; compare: textbook on the left half, robust on the right"}};
    const renderer r = {
        .name = "02_sphere",
        .summary = "02_sphere: white spheres on the background colour (the lecture's \"Image so far\")",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = FEATURE_SPHERES,
        .default_width = 512,
        .default_height = 512,
        .builtin = sphere_stage_scene,
        .prepare = sphere_stage_prepare,
        .context = &formula,
        .sample = sample,
        .pixel_to_image = pixel_to_image,
        .release = sphere_stage_release,
    };
    return renderer_main(&r, argc, argv);
}
