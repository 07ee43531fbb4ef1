/* surface.c - chapter 04: the surfaces of the list, one at a time. */
#include "04_many_shapes/surface.h"

#include <stdlib.h>

#include "03_triangle/triangle_explain.h"
#include "explain.h"
#include "grow.h"

void surface_list_init(surface_list *list, sphere_formula formula, triangle_test test)
{
    *list = (surface_list){.sphere_formula = formula, .triangle_test = test};
}

void surface_list_free(surface_list *list)
{
    free(list->items);
    list->items = NULL;
    list->n = list->capacity = 0;
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

/* snippet: surface_intersect */
bool surface_intersect(const surface *s, const surface_list *list, ray r, real t_min, real t_max, hit_record *hit)
{
    real t, beta = 0, gamma = 0;
    vec3 n;
    EXPLAIN(explain_surface((int)(s - list->items), s->source, s->face));
    if (s->kind == SHAPE_SPHERE) {
        if (!sphere_intersect(&s->sphere, r, t_min, t_max, list->sphere_formula, &t, &n))
            return false;
    } else {
        triangle_hit th;
        bool found = triangle_intersect(&s->triangle, r, t_min, t_max, list->triangle_test, &th);
        EXPLAIN(triangle_explain(&s->triangle, r, t_min, t_max, list->triangle_test, found, &th));
        if (!found)
            return false;
        t = th.t;
        beta = th.beta;
        gamma = th.gamma;
        n = triangle_normal(&s->triangle);
    }
    *hit = surface_hit_record(s, r, t, n, beta, gamma);
    return true;
}
/* end snippet */

hit_record surface_hit_record(const surface *s, ray r, real t, vec3 n, real beta, real gamma)
{
    return (hit_record){
        .t = t,
        .point = ray_at(r, t),
        .normal = n,
        .surface = -1, /* the list's loop fills it in */
        .source = s->source,
        .face = s->face,
        .shader = s->shader,
        .beta = beta,
        .gamma = gamma,
    };
}
