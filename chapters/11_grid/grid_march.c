/* grid_march.c - chapter 11: the closest hit, cell by cell along the ray. */
#include "11_grid/grid.h"
#include "exercise.h"

#include <math.h>

#include "explain.h"

/* The search so far: the best hit, and the window a new hit must fall in. */
typedef struct {
    const surface_list *list;
    ray r;
    real t_min;
    real best_t; /* the t of the best hit, t_max before any */
    int best;    /* its surface, -1 before any */
    hit_record hit;
    uint64_t tests;
} search;

/* snippet: test_surface */
/* Surface k against the ray.  The linear scan keeps the first surface in
 * the list among those hit at the smallest t; the grid meets the surfaces
 * in another order, so it also asks for hits AT the best t so far and takes
 * one there when its index is smaller. */
static void test_surface(search *s, uint32_t k)
{
    hit_record candidate;
    s->tests++;
    if (surface_intersect(&s->list->items[k], s->list, s->r, s->t_min, real_next_up(s->best_t), &candidate) &&
        (candidate.t < s->best_t || (int)k < s->best)) {
        s->best_t = candidate.t;
        s->best = (int)k;
        s->hit = candidate;
        s->hit.surface = (int)k;
    }
}
/* end snippet */

/* The march's state: the cell (i_x, i_y, i_z), the direction of each
 * axis's steps, and the t where the ray crosses the cell's far boundary of
 * each axis (infinity on an axis the ray never crosses). */
typedef struct {
    int i[3], step[3];
    real next[3];
} dda;

static real get(vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

/* t where the ray crosses boundary `plane` of axis a (lo_a + plane cell_a). */
static real crossing(const grid *g, int a, int plane, ray r, const real inv_d[3])
{
    return (get(g->lo, a) + (real)plane * get(g->cell, a) - get(r.p, a)) * inv_d[a];
}

/* snippet: enter */
/* Where the ray enters and leaves the grid's box within (t_min, t_max):
 * false when it misses the box.  Each crossing is widened by its axis's
 * rounding slack, so the march errs towards a cell too many. */
static bool enter_box(const grid *g, ray r, const real inv_d[3], const real slack[3], real *t0, real *t1)
{
    /* TODO enter: the ray against the grid's box, slab by slab (README, "Entering the grid"),
     * narrowing [*t0, *t1]; an axis whose inv_d is 0 never crosses a boundary: the ray is inside
     * that slab or misses the box. */
    EXERCISE_STUB("11_grid", "grid_march.c", "enter"); /* delete this line when done */
    (void)g;
    (void)r;
    (void)inv_d;
    (void)slack;
    (void)t0;
    (void)t1;
    return false;
}
/* end snippet */

/* snippet: dda_step */
/* Leaves the cell through its boundary of axis a: false when that boundary
 * is the grid's own, true after moving to the neighbour. */
static bool dda_step(const grid *g, dda *m, int a, ray r, const real inv_d[3])
{
    /* TODO dda_step: one step of the 3D-DDA along axis a (README, "From cell to cell"): the
     * neighbour's index, whether it is still in the grid, and the t of its far boundary along a,
     * computed from the boundary itself with crossing(), not by adding a step to the old t. */
    EXERCISE_STUB("11_grid", "grid_march.c", "dda_step"); /* delete this line when done */
    (void)g;
    (void)m;
    (void)a;
    (void)r;
    (void)inv_d;
    (void)crossing;
    return false;
}
/* end snippet */

/* The cell index along axis a of a point at coordinate x, clamped to the grid. */
static int cell_of(const grid *g, int a, real x)
{
    real f = (x - get(g->lo, a)) / get(g->cell, a);
    if (!(f >= 0)) /* also NaN */
        return 0;
    return f >= (real)(g->n[a] - 1) ? g->n[a] - 1 : (int)f;
}

/* Visits the cells r pierces, in order, testing each one's surfaces into
 * *s, until the stop rule ends the march; returns the cells visited. */
static uint64_t march(const grid *g, search *s, ray r, real t_min, real t_max)
{
    /* Rounding moves a computed crossing by a few REAL_EPSILON times the
     * coordinates involved: `reach` bounds that in length, slack_a in t. */
    const real reach = 16 * REAL_EPSILON * (vec3_max_abs(r.p) + real_fmax(vec3_max_abs(g->lo), vec3_max_abs(g->hi)));
    real inv_d[3], slack[3], t0 = t_min, t1 = t_max;
    for (int a = 0; a < 3; a++) {
        inv_d[a] = 1 / get(r.d, a);
        if (!isfinite(inv_d[a])) /* d_a = +0 or -0, or so small that 1/d_a overflows */
            inv_d[a] = 0;
        slack[a] = reach * real_abs(inv_d[a]);
    }
    if (g->n_cells == 0 || !enter_box(g, r, inv_d, slack, &t0, &t1))
        return 0;
    uint64_t cells = 0;

    /* snippet: march */
    /* The first cell holds p + t0 d, moved back along the ray by the rounding of that point. */
    dda m;
    const real back = reach + 16 * REAL_EPSILON * real_abs(t0) * vec3_max_abs(r.d);
    for (int a = 0; a < 3; a++) {
        m.step[a] = inv_d[a] > 0 ? 1 : inv_d[a] < 0 ? -1 : 0;
        real x = m.step[a] ? get(r.p, a) + t0 * get(r.d, a) : get(r.p, a);
        m.i[a] = cell_of(g, a, x - (real)m.step[a] * back);
        m.next[a] = m.step[a] ? crossing(g, a, m.i[a] + (m.step[a] > 0), r, inv_d) : REAL_INFINITY;
    }
    for (;;) {
        /* Every surface of the cell, over the whole window: a hit beyond the cell is kept too. */
        cells++;
        long c = m.i[0] + (long)g->n[0] * (m.i[1] + (long)g->n[1] * m.i[2]);
        EXPLAIN(explain_cell(m.i[0], m.i[1], m.i[2], (long)(g->start[c + 1] - g->start[c])));
        for (uint32_t e = g->start[c]; e < g->start[c + 1]; e++)
            test_surface(s, g->refs[e]);
        /* The cell ends where the ray crosses its nearest boundary. */
        int a = m.next[0] < m.next[1] ? (m.next[0] < m.next[2] ? 0 : 2) : (m.next[1] < m.next[2] ? 1 : 2);
        /* TODO stop: the stop rule (README, "When to stop"): end the march once the best hit
         * lies in this cell, allowing for the boundary's rounding slack; else step to the next cell. */
        EXERCISE_STUB("11_grid", "grid_march.c", "stop"); /* delete this line when done */
        (void)slack;
        break;
        if (!dda_step(g, &m, a, r, inv_d))
            break;
    }
    /* end snippet */
    return cells;
}

bool grid_intersect_counted(const grid *g, ray r, real t_min, real t_max, hit_record *hit, grid_counts *counts)
{
    search s = {.list = g->list, .r = r, .t_min = t_min, .best_t = t_max, .best = -1};
    for (long u = 0; u < g->n_unbinned; u++)
        test_surface(&s, g->unbinned[u]);
    uint64_t cells = march(g, &s, r, t_min, t_max);
    if (counts) {
        counts->cells += cells;
        counts->tests += s.tests;
    }
    if (s.best < 0)
        return false;
    *hit = s.hit;
    return true;
}

bool grid_intersect(const grid *g, ray r, real t_min, real t_max, hit_record *hit)
{
    return grid_intersect_counted(g, r, t_min, t_max, hit, NULL);
}
