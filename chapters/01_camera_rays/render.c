/* render.c - chapter 01's renderer: a picture of the eye rays.
 *
 * Nothing is intersected yet, so the picture shows the rays themselves:
 *   --show=direction  colour = (d/|d| + 1) / 2, the ray's direction as RGB;
 *   --show=floor      a checkerboard where the ray crosses the plane y = 0
 *                     (t = -p_y / d_y), sky above the horizon: perspective
 *                     makes the squares shrink with distance, orthographic
 *                     keeps them the same size.
 */
#include <stdlib.h>

#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "renderer.h"

enum { SHOW_DIRECTION, SHOW_FLOOR };
static const char *const show_choices[] = {"direction", "floor", NULL};
static int show = SHOW_DIRECTION;

static const knob knobs[] = {
    {"show", KNOB_CHOICE, &show, show_choices, "what to colour each ray by"},
};

static color direction_color(ray r)
{
    vec3 d = vec3_normalize(r.d);
    return color_make((d.x + 1) / 2, (d.y + 1) / 2, (d.z + 1) / 2);
}

/* snippet: floor */
static color floor_color(ray r)
{
    if (r.d.y < 0 && r.p.y > 0) {
        real t = -r.p.y / r.d.y; /* p_y + t d_y = 0 */
        vec3 x = ray_at(r, t);
        int odd = ((long)real_floor(x.x) + (long)real_floor(x.z)) & 1;
        return odd ? color_make((real)0.9, (real)0.9, (real)0.85) : color_make((real)0.1, (real)0.1, (real)0.15);
    }
    real up = r.d.y / vec3_length(r.d); /* sky: brighter towards the zenith */
    return color_make((real)0.4 + (real)0.2 * up, (real)0.6 + (real)0.2 * up, (real)0.9);
}
/* end snippet */

static color sample(const void *scene, real u, real v, uint64_t *rays)
{
    ray r = camera_ray(scene, u, v);
    ++*rays;
    if (!(vec3_max_abs(r.d) > 0)) /* an unfinished camera: black, not NaN */
        return color_make(0, 0, 0);
    return show == SHOW_FLOOR ? floor_color(r) : direction_color(r);
}

/* A camera 2 units above the floor, looking ahead and down, with a wide view. */
static int builtin(scene *desc)
{
    desc->has_camera = true;
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 2, 6},
        .view_dir = {0, -0.3, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 1,
        .view_width = 2,
        .view_height = 1.5,
    };
    return 0;
}

static void *prepare(const scene *desc, char *err, size_t err_size)
{
    camera *cam = malloc(sizeof *cam);
    if (!cam) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    if (!camera_from_scene(cam, desc, err, err_size)) {
        free(cam);
        return NULL;
    }
    return cam;
}

int main(int argc, char **argv)
{
    const renderer r = {
        .name = "01_camera_rays",
        .summary = "01_camera_rays: the eye rays of a camera, coloured by direction (or where they meet the floor)",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = 0,
        .default_width = 512,
        .default_height = 384,
        .builtin = builtin,
        .prepare = prepare,
        .sample = sample,
        .pixel_to_image = pixel_to_image,
        .release = free,
    };
    return renderer_main(&r, argc, argv);
}
