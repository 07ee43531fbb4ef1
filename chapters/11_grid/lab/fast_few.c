/* fast_few.c - chapter 11's lab: a scene of few surfaces is tested as a list, without cells. */
#include <stdlib.h>

#include "11_grid/lab/fast_boxes.h"
#include "11_grid/lab/fast_build.h"

/* What a ray's test of each kind of unit costs, in quarters of a triangle
 * test: the lab's times of scenes of a floor and k boxes, spheres or
 * triangles, listed and gridded (the lab's README, "Few surfaces"). */
enum { QUARTERS_TRIANGLE = 4, QUARTERS_BOX = 5, QUARTERS_SPHERE = 16 };

/* The entry of surface k in the list, as the packed lists have it (k, or
 * FAST_GRID_BOX + its box, by the box's first triangle), or FAST_BOX_NONE
 * for no entry: a box's other triangles, a surface without finite bounds
 * (g->unbinned, tested apart). */
static uint32_t unit_entry(const fast_grid *g, const surface_list *list, long k)
{
    vec3 lo, hi;
    fast_grid_surface_bounds(&list->items[k], &lo, &hi);
    const uint32_t b = g->boxes ? g->boxes->of[k] : FAST_BOX_NONE;
    if (!vec3_is_finite(lo) || !vec3_is_finite(hi) || (b != FAST_BOX_NONE && g->boxes->box[b].first != (uint32_t)k))
        return FAST_BOX_NONE;
    return b == FAST_BOX_NONE ? (uint32_t)k : FAST_GRID_BOX + b;
}

bool fast_grid_few_units(fast_grid *g, const surface_list *list, int up_to)
{
    /* the units and their cost */
    long n = 0;
    long long quarters = 0;
    for (long k = 0; k < list->n; k++) {
        const uint32_t e = unit_entry(g, list, k);
        if (e == FAST_BOX_NONE)
            continue;
        const bool sphere = list->items[k].kind == SHAPE_SPHERE;
        n++;
        quarters += e >= FAST_GRID_BOX ? QUARTERS_BOX : sphere ? QUARTERS_SPHERE : QUARTERS_TRIANGLE;
        if (quarters > 4 * (long long)up_to)
            return true; /* too many: cells */
    }
    if (n == 0)
        return true;
    g->units = malloc((size_t)n * sizeof *g->units);
    if (!g->units)
        return false;
    for (long k = 0; k < list->n; k++) {
        const uint32_t e = unit_entry(g, list, k);
        if (e != FAST_BOX_NONE)
            g->units[g->n_units++] = e;
    }
    g->peak_bytes = fast_grid_memory(g);
    g->n[0] = g->n[1] = g->n[2] = 0; /* no cells; the box, for the rays that miss it */
    g->lo_a[0] = g->lo.x, g->lo_a[1] = g->lo.y, g->lo_a[2] = g->lo.z;
    g->hi_a[0] = g->hi.x, g->hi_a[1] = g->hi.y, g->hi_a[2] = g->hi.z;
    return true;
}
