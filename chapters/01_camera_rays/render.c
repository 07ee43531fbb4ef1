/* render.c - chapter 01's renderer: a picture of the eye rays (ray_view.h).
 *
 * --show=direction colours each ray by its direction, --show=floor by where
 * it crosses the plane y = 0. */
#include <stdlib.h>

#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "01_camera_rays/ray_view.h"
#include "renderer.h"

enum { SHOW_DIRECTION, SHOW_FLOOR };
static const char *const show_choices[] = {"direction", "floor", NULL};

typedef struct { camera cam; int show; /* --show */ } ray_picture;

static color sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const ray_picture *pic = prepared;
    ray r = camera_ray(&pic->cam, u, v);
    ++*rays;
    if (!(vec3_max_abs(r.d) > 0)) /* an unfinished camera: black, not NaN */
        return color_make(0, 0, 0);
    return pic->show == SHOW_FLOOR ? floor_color(r) : direction_color(r);
}

static void *prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    ray_picture *pic = malloc(sizeof *pic);
    if (pic && camera_from_scene(&pic->cam, desc, err, err_size)) {
        pic->show = *(const int *)context; /* main's --show */
        return pic;
    }
    if (!pic)
        snprintf(err, err_size, "out of memory");
    free(pic);
    return NULL;
}

int main(int argc, char **argv)
{
    int show = SHOW_DIRECTION;
    const knob knobs[] = {{"show", KNOB_CHOICE, &show, show_choices, "what to colour each ray by"}};
    const renderer r = {
        .name = "01_camera_rays",
        .summary = "01_camera_rays: the eye rays of a camera, coloured by direction (or where they meet the floor)",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = 0,
        .default_width = 512,
        .default_height = 384,
        .builtin = ray_view_scene,
        .prepare = prepare,
        .context = &show,
        .sample = sample,
        .pixel_to_image = pixel_to_image,
        .release = free,
    };
    return renderer_main(&r, argc, argv);
}
