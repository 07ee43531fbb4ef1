/* grid_march.c - chapter 11: the closest hit, cell by cell along the ray. */
#include "11_grid/grid.h"
#include "exercise.h"

#include "explain.h"

/* The search so far: the best hit (surface -1 and t = t_max before any) and the tests made. */
typedef struct {
    const surface_list *list;
    ray r;
    real t_min, best_t;
    int best;
    hit_record hit;
    uint64_t tests;
} search;

/* Surface k against the ray, also AT the best t so far: there it wins when it is earlier in the list. */
static void test_surface(search *s, uint32_t k)
{
    hit_record candidate;
    s->tests++;
    if (surface_intersect(&s->list->items[k], s->list, s->r, s->t_min, real_next_up(s->best_t), &candidate) &&
        (candidate.t < s->best_t || (int)k < s->best)) {
        s->best_t = candidate.t, s->best = (int)k;
        s->hit = candidate, s->hit.surface = (int)k;
    }
}

/* The march: the cell i, each axis's step (+1, -1 or 0) and the t of the cell's far boundary along it. */
typedef struct { int i[3], step[3]; real next[3]; } dda;

/* t where the ray crosses boundary `plane` of axis a, lo_a + plane cell_a. */
static real crossing(const grid *g, int a, int plane, ray r, const real inv_d[3])
{
    return (vec3_axis(g->lo, a) + (real)plane * vec3_axis(g->cell, a) - vec3_axis(r.p, a)) * inv_d[a];
}

/* Narrows [*t0, *t1] to where the ray is inside the grid's box, each crossing
 * widened by its axis's slack: false when the ray misses the box. */
static bool enter_box(const grid *g, ray r, const real inv_d[3], const real slack[3], real *t0, real *t1)
{
    /* TODO enter: the ray against the grid's box, slab by slab (README, "Entering the grid"),
     * narrowing [*t0, *t1]; an axis whose inv_d is 0 never crosses a boundary: the ray is inside
     * that slab or misses the box. */
    EXERCISE_STUB("11_grid", "grid_march.c", "enter"); /* delete this line when done */
    (void)g, (void)r, (void)inv_d, (void)slack, (void)t0, (void)t1;
    return false;
}

/* Moves to the neighbour across the cell's boundary of axis a: false when that boundary is the grid's own. */
static bool dda_step(const grid *g, dda *m, int a, ray r, const real inv_d[3])
{
    /* TODO dda_step: one step of the 3D-DDA along axis a (README, "From cell to cell"): the
     * neighbour's index, whether it is still in the grid, and the t of its far boundary along a,
     * computed from the boundary itself with crossing(), not by adding a step to the old t. */
    EXERCISE_STUB("11_grid", "grid_march.c", "dda_step"); /* delete this line when done */
    (void)g, (void)m, (void)a, (void)r, (void)inv_d, (void)crossing;
    return false;
}

bool grid_intersect_counted(const grid *g, ray r, real t_min, real t_max, hit_record *hit, grid_counts *counts)
{
    search s = {.list = g->list, .r = r, .t_min = t_min, .best_t = t_max, .best = -1};
    for (uint32_t e = g->start[g->n_cells]; e < g->start[g->n_cells + 1]; e++) /* the surfaces without bounds */
        test_surface(&s, g->refs[e]);
    real inv_d[3], slack[3], t0 = t_min, t1 = t_max;
    const real reach = box_ray_slack((box){g->lo, g->hi}, r, inv_d, slack);
    uint64_t cells = 0;
    if (g->n_cells > 0 && enter_box(g, r, inv_d, slack, &t0, &t1)) {
        /* snippet: march */
        /* The first cell holds p + t0 d, moved back along the ray by the rounding of that point. */
        dda m;
        const real back = reach + 16 * REAL_EPSILON * real_abs(t0) * vec3_max_abs(r.d);
        for (int a = 0; a < 3; a++) {
            m.step[a] = inv_d[a] > 0 ? 1 : inv_d[a] < 0 ? -1 : 0;
            real x = m.step[a] ? vec3_axis(r.p, a) + t0 * vec3_axis(r.d, a) : vec3_axis(r.p, a);
            x -= (real)m.step[a] * back;
            m.i[a] = real_to_index((x - vec3_axis(g->lo, a)) / vec3_axis(g->cell, a), 0, g->n[a] - 1);
            m.next[a] = m.step[a] ? crossing(g, a, m.i[a] + (m.step[a] > 0), r, inv_d) : REAL_INFINITY;
        }
        for (;;) {
            /* Every surface of the cell, over the whole window: a hit beyond the cell is kept too. */
            cells++;
            long c = m.i[0] + (long)g->n[0] * (m.i[1] + (long)g->n[1] * m.i[2]);
            EXPLAIN(explain_cell(m.i[0], m.i[1], m.i[2], (long)(g->start[c + 1] - g->start[c])));
            for (uint32_t e = g->start[c]; e < g->start[c + 1]; e++)
                test_surface(&s, g->refs[e]);
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
    }
    if (counts)
        counts->cells += cells, counts->tests += s.tests;
    if (s.best >= 0)
        *hit = s.hit;
    return s.best >= 0;
}
