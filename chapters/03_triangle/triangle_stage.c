/* triangle_stage.c - chapter 03: what its renderer traces, and how --explain reports a test. */
#include "03_triangle/triangle_stage.h"

#include <stdlib.h>

#include "01_camera_rays/pixel.h"
#include "03_triangle/scenes/triangle_scene.h"
#include "03_triangle/triangle_explain.h"
#include "explain.h"

static const char *const triangle_choices[] = {"cramer", "watertight", NULL}; /* in the order of the enum */

knob triangle_knob(int *choice)
{
    return (knob){"triangle", KNOB_CHOICE, choice, triangle_choices, "ray-triangle test (chapter 03)"};
}

void triangle_explain(const triangle *tri, ray r, real t_min, real t_max, triangle_test kind, bool found,
                      const triangle_hit *hit)
{
    if (found) {
        explain_triangle(true, hit->t, hit->beta, hit->gamma, t_min, t_max, true, hit->t);
        return;
    }
    triangle_hit line;
    bool line_hits = triangle_intersect(tri, r, -REAL_INFINITY, REAL_INFINITY, kind, &line);
    explain_triangle(false, 0, 0, 0, t_min, t_max, line_hits, line_hits ? line.t : 0);
}

/* Every hit found becomes the far end of the window for the rest. */
int triangle_stage_closest(const triangle_stage *s, ray r, triangle_test t, triangle_hit *best)
{
    int found = -1;
    real t_max = REAL_INFINITY;
    for (int k = 0; k < s->n; k++) {
        EXPLAIN(explain_surface(k, k, 0));
        bool hit = triangle_intersect(&s->tris[k], r, 0, t_max, t, best);
        EXPLAIN(triangle_explain(&s->tris[k], r, 0, t_max, t, hit, best));
        if (hit) {
            t_max = best->t;
            found = k;
        }
    }
    return found;
}

color barycentric_color(triangle_hit h)
{
    real alpha = 1 - h.beta - h.gamma;
    return color_make(alpha, h.beta, h.gamma);
}

color triangle_stage_sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const triangle_stage *s = prepared;
    ray r = camera_ray(&s->cam, u, v);
    ++*rays;
    triangle_hit h;
    int k = triangle_stage_closest(s, r, s->test, &h);
    if (k < 0)
        return s->back;
    EXPLAIN(explain_closest(k, k, h.t, ray_at(r, h.t)));
    return barycentric_color(h);
}

void *triangle_stage_prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    const int *test = context; /* --triangle's value, owned by main */
    triangle_stage *s = calloc(1, sizeof *s + (size_t)desc->n_surfaces * sizeof s->tris[0]);
    if (!s)
        snprintf(err, err_size, "%s: out of memory", scene_name(desc));
    if (!s || !camera_from_scene(&s->cam, desc, err, err_size)) {
        free(s);
        return NULL;
    }
    s->back = desc->back_color;
    s->test = (triangle_test)*test;
    for (int k = 0; k < desc->n_surfaces; k++)
        if (desc->surfaces[k].kind == SURFACE_TRIANGLE)
            s->tris[s->n++] = (triangle){desc->surfaces[k].v0, desc->surfaces[k].v1, desc->surfaces[k].v2};
    return s;
}

renderer triangle_stage_renderer(int *test, knob *row)
{
    *row = triangle_knob(test);
    return (renderer){
        .name = "03_triangle",
        .summary = "03_triangle: triangles coloured by their barycentric coordinates",
        .knobs = row,
        .n_knobs = 1,
        .modelled = FEATURE_TRIANGLES,
        .default_width = 512,
        .default_height = 384,
        .builtin = triangle_scene,
        .prepare = triangle_stage_prepare,
        .context = test,
        .sample = triangle_stage_sample,
        .release = free,
        .pixel_to_image = pixel_to_image,
    };
}
