/* ray_view.c - chapter 01: what the renderer shows of an eye ray, and its built-in scene. */
#include "01_camera_rays/ray_view.h"

color direction_color(ray r)
{
    vec3 d = vec3_normalize(r.d);
    return color_make((d.x + 1) / 2, (d.y + 1) / 2, (d.z + 1) / 2);
}

color floor_color(ray r)
{
    if (r.d.y < 0 && r.p.y > 0) {
        real t = -r.p.y / r.d.y; /* p_y + t d_y = 0 */
        vec3 x = ray_at(r, t);
        int odd = real_is_odd(real_floor(x.x)) != real_is_odd(real_floor(x.z)); /* range-safe: no (long) */
        return odd ? color_make((real)0.9, (real)0.9, (real)0.85) : color_make((real)0.1, (real)0.1, (real)0.15);
    }
    real up = r.d.y / vec3_length(r.d); /* sky: brighter towards the zenith */
    return color_make((real)0.4 + (real)0.2 * up, (real)0.6 + (real)0.2 * up, (real)0.9);
}

int ray_view_scene(scene *desc)
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
