/* fast_search.h - chapter 11's lab: the closest-hit search a march carries along its cells.
 *
 * The best hit so far and the window a new one must fall in; each surface a
 * cell lists goes through test_surface.  Triangles of a watertight list take
 * chapter 03's watertight_ray_hit with the ray's part made once per ray, and
 * only the final hit gets its record (search_record): the same bits as
 * surface_intersect, with less work per triangle.
 */
#ifndef CH11_LAB_FAST_SEARCH_H
#define CH11_LAB_FAST_SEARCH_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "03_triangle/triangle.h"
#include "04_many_shapes/surface.h"

/* The search so far: the best hit, and the window a new hit must fall in. */
typedef struct {
    const surface_list *list;
    ray r;
    real t_min;
    real best_t;        /* the t of the best hit, t_max before any */
    real upper;         /* surfaces are asked for hits in (t_min, upper) */
    int best;           /* its surface, -1 before any */
    bool recorded;      /* its record is in `hit` (surface_intersect's); else its beta and gamma are in `tri` */
    hit_record hit;
    triangle_hit tri;
    int by_ray;         /* triangles take the watertight test with the ray's part made once, `wr`:
                         * 1 yes, 0 no, -1 not known before the first triangle */
    watertight_ray wr;
    uint64_t tests;
} search;

/* The search for ray r in (t_min, t_max), before any surface.  The record,
 * the triangle hit and the ray's watertight part are written before they are
 * read, so they are left as they are here (they are most of the struct). */
static inline void search_start(search *s, const surface_list *list, ray r, real t_min, real t_max)
{
    s->list = list;
    s->r = r;
    s->t_min = t_min;
    s->best_t = s->upper = t_max;
    s->best = -1;
    s->recorded = false;
    s->by_ray = list->triangle_test == TRIANGLE_WATERTIGHT ? -1 : 0;
    s->tests = 0;
}

/* Whether the triangles take the ray's own watertight test.  For a watertight
 * list, chapter 03's watertight_ray_hit with the ray's permutation and shear
 * made once, at the first triangle (many rays test none): triangle_intersect
 * does the same arithmetic for every triangle, unless d is so long or short
 * that it first scales it (then every surface takes surface_intersect, as
 * there). */
static inline bool triangles_by_ray(search *s)
{
    if (s->by_ray < 0)
        s->by_ray = vec3_scale_exponent(s->r.d) == 0 && watertight_ray_make(s->r, &s->wr);
    return s->by_ray;
}

/* The next real above t: real_next_up, whose library call costs some forty
 * instructions; a positive finite t is its bits plus one (an IEEE number's
 * bits, read as an integer, count up with it). */
static inline real next_above(real t)
{
#ifdef RT_REAL_FLOAT
    uint32_t bits;
#else
    uint64_t bits;
#endif
    _Static_assert(sizeof bits == sizeof t, "an integer as wide as a real");
    if (!(t > 0 && t < REAL_INFINITY))
        return real_next_up(t);
    memcpy(&bits, &t, sizeof t);
    bits++;
    memcpy(&t, &bits, sizeof t);
    return t;
}

/* The new best hit: surface k at t. */
static inline void take(search *s, uint32_t k, real t)
{
    s->best_t = t;
    s->upper = next_above(t);
    s->best = (int)k;
}

/* snippet: test_surface */
/* Surface k against the ray.  The linear scan keeps the first surface in
 * the list among those hit at the smallest t; the grid meets the surfaces
 * in another order, so it also asks for hits AT the best t so far (upper is
 * the next real above it) and takes one there when its index is smaller.
 * A triangle's record waits for the end of the search (search_record): most
 * hits found along the way lose to a later one. */
static inline void test_surface(search *s, uint32_t k)
{
    const surface *item = &s->list->items[k];
    s->tests++;
    if (item->kind == SHAPE_TRIANGLE && s->by_ray && triangles_by_ray(s)) {
        triangle_hit th;
        if (watertight_ray_hit(&s->wr, &item->triangle, s->t_min, s->upper, &th) &&
            (th.t < s->best_t || (int)k < s->best)) {
            take(s, k, th.t);
            s->tri = th;
            s->recorded = false;
        }
        return;
    }
    hit_record candidate;
    if (surface_intersect(item, s->list, s->r, s->t_min, s->upper, &candidate) &&
        (candidate.t < s->best_t || (int)k < s->best)) {
        take(s, k, candidate.t);
        s->hit = candidate;
        s->recorded = true;
    }
}
/* end snippet */

/* The best hit's record, as surface_intersect would have filled it in;
 * `normal`: each triangle's triangle_normal, made at build time, or NULL. */
static inline hit_record search_record(const search *s, const vec3 *normal)
{
    hit_record h = s->hit;
    if (!s->recorded) {
        const surface *item = &s->list->items[s->best];
        const vec3 n = normal ? normal[s->best] : triangle_normal(&item->triangle);
        h = surface_hit_record(item, s->r, s->best_t, n, s->tri.beta, s->tri.gamma);
    }
    h.surface = s->best;
    return h;
}

#endif
