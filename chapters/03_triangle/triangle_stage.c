/* triangle_stage.c - chapter 03: what its renderer traces, and its built-in scene. */
#include "03_triangle/triangle_stage.h"

#include <stdlib.h>

#include "01_camera_rays/pixel.h"
#include "03_triangle/scenes/icosahedron.h"
#include "03_triangle/triangle_explain.h"
#include "explain.h"
#include "scene_build.h"

static const char *const triangle_choices[] = {"cramer", "watertight", NULL}; /* in the order of the enum */

knob triangle_knob(int *choice)
{
    return (knob){"triangle", KNOB_CHOICE, choice, triangle_choices, "ray-triangle test (chapter 03)"};
}


/* The closest hit among all triangles: every hit found becomes the far end
 * of the window for the rest, so at the end the nearest one is left.  (The
 * closest hit over all kinds of shapes is chapter 04's subject.) */
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

/* snippet: barycentric_color */
color barycentric_color(triangle_hit h)
{
    real alpha = 1 - h.beta - h.gamma;
    return color_make(alpha, h.beta, h.gamma);
}
/* end snippet */

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

static int add_triangle(scene *desc, vec3 v0, vec3 v1, vec3 v2)
{
    scene_surface surface = {.kind = SURFACE_TRIANGLE, .shader = -1, .v0 = v0, .v1 = v1, .v2 = v2};
    return scene_add_surface(desc, surface);
}

int triangle_scene_add_icosahedron(scene *desc, vec3 centre, real radius)
{
    vec3 v[ICOSAHEDRON_VERTICES];
    triangle faces[ICOSAHEDRON_FACES];
    icosahedron_vertices(centre, radius, v);
    icosahedron_triangles(v, faces);
    for (int f = 0; f < ICOSAHEDRON_FACES; f++)
        if (add_triangle(desc, faces[f].a, faces[f].b, faces[f].c) < 0)
            return -1;
    return 0;
}

int triangle_scene(scene *desc)
{
    desc->has_camera = true;
    desc->back_color = color_make((real)0.01, (real)0.01, (real)0.015);
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 0, 6},
        .view_dir = {0, 0, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 1,
        .view_width = 1.2,
        .view_height = 0.9,
    };
    if (add_triangle(desc, vec3_make(-3, -1.6, 0), vec3_make(-0.2, -1.6, 0), vec3_make(-1.6, 1.8, 0)) < 0)
        return -1;
    return triangle_scene_add_icosahedron(desc, vec3_make(1.6, 0, -0.5), (real)1.4);
}

void triangle_stage_release(void *prepared)
{
    triangle_stage *s = prepared;
    if (s)
        free(s->tris);
    free(s);
}

void *triangle_stage_prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    const int *test = context; /* --triangle's value, owned by main */
    const char *where = scene_name(desc);
    triangle_stage *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, err_size, "%s: out of memory", where);
        return NULL;
    }
    if (!camera_from_scene(&s->cam, desc, err, err_size)) {
        free(s);
        return NULL;
    }
    s->back = desc->back_color;
    s->test = (triangle_test)*test;
    s->tris = malloc((size_t)(desc->n_surfaces ? desc->n_surfaces : 1) * sizeof *s->tris);
    if (!s->tris) {
        snprintf(err, err_size, "%s: out of memory", where);
        triangle_stage_release(s);
        return NULL;
    }
    for (int k = 0; k < desc->n_surfaces; k++) {
        const scene_surface *surface = &desc->surfaces[k];
        if (surface->kind == SURFACE_TRIANGLE)
            s->tris[s->n++] = (triangle){surface->v0, surface->v1, surface->v2};
    }
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
        .release = triangle_stage_release,
        .pixel_to_image = pixel_to_image,
    };
}
