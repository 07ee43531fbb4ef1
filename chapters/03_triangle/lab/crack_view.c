/* crack_view.c - chapter 03's lab: the cracks of a closed mesh, seen from inside. */
#include "03_triangle/lab/crack_view.h"

#include "03_triangle/lab/cracks.h"
#include "03_triangle/scenes/triangle_scene.h"

/* How close to an edge, in barycentric units, a pixel is re-aimed at the
 * edge, and the stretch of the edge (as a fraction of its length, to either
 * side) that it stands for: about a pixel's width. */
#define CRACK_EDGE_WIDTH ((real)0.012)
#define CRACK_STRETCH ((real)0.003)
enum { CRACK_RAYS = 16 };

int crack_scene(scene *desc)
{
    desc->has_camera = true;
    desc->back_color = color_make((real)0.01, (real)0.01, (real)0.015);
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0.12, -0.08, 0.15},
        .view_dir = {0.35, 0.25, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 1,
        .view_width = 2.0,
        .view_height = 2.0,
    };
    return triangle_scene_add_icosahedron(desc, vec3_make(0, 0, 0), 1);
}

/* snippet: crack_color */
color crack_color(const triangle_stage *s, ray r, uint64_t *rays)
{
    triangle_hit h;
    /* Where the pixel looks, found with the test that has no cracks. */
    int k = triangle_stage_closest(s, r, TRIANGLE_WATERTIGHT, &h);
    if (k < 0)
        return s->back;
    vec3 e0, e1;
    real s0;
    if (!near_edge(&s->tris[k], h.beta, h.gamma, CRACK_EDGE_WIDTH, &e0, &e1, &s0))
        return color_scale(barycentric_color(h), (real)0.08); /* the faces, dark */
    /* The pixel's stretch of the edge, s0 +- CRACK_STRETCH: rays aimed exactly at
     * CRACK_RAYS points of it (all at the vertex when e0 = e1). */
    for (int j = 0; j < CRACK_RAYS; j++) {
        real sj = s0 + CRACK_STRETCH * (2 * (real)j / (CRACK_RAYS - 1) - 1);
        vec3 x = edge_point(e0, e1, real_fmin(1, real_fmax(0, sj)));
        ray aimed = {r.p, vec3_sub(x, r.p)};
        ++*rays;
        if (!hits_any(s->tris, s->n, aimed, s->test))
            return color_make(1, 0, 0); /* slipped through a crack */
    }
    return color_make((real)0.25, (real)0.25, (real)0.25);
}
/* end snippet */

color crack_sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const triangle_stage *s = prepared;
    ray r = camera_ray(&s->cam, u, v);
    ++*rays;
    return crack_color(s, r, rays);
}
