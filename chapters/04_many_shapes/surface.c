/* surface.c - chapter 04: the surfaces of the list, one at a time. */
#include "04_many_shapes/surface.h"

#include <stdlib.h>

#include "03_triangle/triangle_explain.h"
#include "explain.h"
#include "grow.h"
#include "scene_shapes.h"

void surface_list_init(surface_list *list, sphere_formula formula, triangle_test test)
{
    *list = (surface_list){.sphere_formula = formula, .triangle_test = test};
}

void surface_list_free(surface_list *list)
{
    free(list->items);
    *list = (surface_list){.sphere_formula = list->sphere_formula, .triangle_test = list->triangle_test};
}

static int add(surface_list *list, surface s)
{
    if (grow((void **)&list->items, &list->capacity, list->n + 1, sizeof s) != 0)
        return -1;
    list->items[list->n] = s;
    return list->n++;
}

int surface_list_add_sphere(surface_list *list, sphere s, int shader, int source)
{
    return add(list, (surface){.kind = SHAPE_SPHERE, .sphere = s, .shader = shader, .source = source});
}

int surface_list_add_triangle(surface_list *list, triangle tri, int shader, int source)
{
    return add(list, (surface){.kind = SHAPE_TRIANGLE, .triangle = tri, .shader = shader, .source = source});
}

/* Appends one shape of the scene (scene_shapes.h) to the list: its index, or -1. */
static int add_shape(void *list, const scene_shape *s)
{
    int i = s->is_sphere ? surface_list_add_sphere(list, (sphere){s->center, s->radius}, s->shader, s->source)
                         : surface_list_add_triangle(list, (triangle){s->v[0], s->v[1], s->v[2]}, s->shader, s->source);
    if (i >= 0)
        ((surface_list *)list)->items[i].face = s->face;
    return i;
}

int surface_list_from_scene(surface_list *list, const scene *desc, char *err, size_t err_size)
{
    return scene_shapes(desc, add_shape, list, err, err_size);
}

bool surface_intersect(const surface *s, const surface_list *list, ray r, real t_min, real t_max, hit_record *hit)
{
    EXPLAIN(explain_surface((int)(s - list->items), s->source, s->face));
    if (s->kind == SHAPE_SPHERE) {
        real t;
        vec3 n;
        bool found = sphere_intersect(&s->sphere, r, t_min, t_max, list->sphere_formula, &t, &n);
        if (found)
            *hit = surface_hit_record(s, r, t, n, 0, 0);
        return found;
    }
    triangle_hit th;
    bool found = triangle_intersect(&s->triangle, r, t_min, t_max, list->triangle_test, &th);
    EXPLAIN(triangle_explain(&s->triangle, r, t_min, t_max, list->triangle_test, found, &th));
    if (found)
        *hit = surface_hit_record(s, r, th.t, triangle_normal(&s->triangle), th.beta, th.gamma);
    return found;
}

hit_record surface_hit_record(const surface *s, ray r, real t, vec3 n, real beta, real gamma)
{
    return (hit_record){.t = t, .point = ray_at(r, t), .normal = n, .surface = -1, /* set by the list's loop */
                        .source = s->source, .face = s->face, .shader = s->shader, .beta = beta, .gamma = gamma};
}
