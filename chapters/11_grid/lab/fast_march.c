/* fast_march.c - chapter 11's lab: the fast grid's march: mailbox, leaps, batches, two levels, prefetching.
 *
 * The loops over the three axes are unrolled (`#pragma GCC unroll 3`, which
 * clang honours too): gcc's -O2 keeps such a loop rolled, with its per-axis
 * values in memory; unrolled, the query runs 7 % fewer instructions
 * (speed6.md).  On a grid larger than the caches the march prefetches the
 * next cell and the surfaces it is about to test (speed7.md). */
#include "11_grid/lab/fast_grid.h"

#include <math.h>

#include "11_grid/lab/fast_cull.h"
#include "11_grid/lab/fast_noted.h"

/* A cell's entries are sifted this many at a time, by the ray's span in the
 * cell (cull_span) when the cell lists at least SIFT_FROM of them; fewer are
 * tested without culling. */
#define BATCH 32
#define SIFT_FROM 8

/* snippet: dda */
/* The march's state in one grid (Amanatides and Woo): the cell the ray is
 * in and the t at which it crosses the next cell boundary along each axis.
 * The direction of its steps belongs to the ray (ray_frame). */
typedef struct {
    int i[3];     /* the cell's indices */
    real next[3]; /* t of the next boundary crossing along each axis; +infinity when step_a is 0 */
    long cell;    /* i[0] + n_x (i[1] + n_y i[2]): the cell's place in g->start */
    long move[3]; /* step_a stride_a: what a step along a adds to cell, in this grid */
    /* For a leap (dda_leap), the ray in this grid's cells: the point at t, in
     * cells from the low corner and moved back by its rounding, is
     * at0_a + t per_t_a - |t| back_per_t_a, where back (as in enter: reach +
     * 16 REAL_EPSILON |t| d_max, a length) is divided by the cell once per
     * grid, so that a leap takes two products and two sums after t_exit where
     * (p + t d - lo - step back) / cell took five operations in a row, on the
     * chain from one leap to the next (speed9.md); for t >= 0, as every ray
     * the renderers cast has, at0_a + t ahead_per_t_a (per_t_a - back_per_t_a,
     * made with them): one product and one sum (speed11.md).  Its rounding, a
     * few REAL_EPSILON (|p - lo| + |t d|) / cell, is within that back. */
    real at0[3], per_t[3], back_per_t[3], ahead_per_t[3];
} dda;
/* end snippet */

/* t where the ray p + t d crosses plane `plane` (a cell boundary, counted
 * from the grid's low corner) of axis a: lo_a + plane cell_a = p_a + t d_a
 * (g->plane holds lo_a + plane cell_a). */
static inline real crossing(const fast_grid *g, int a, int plane, const real p[3], const real inv_d[3])
{
    return (g->plane[a][plane] - p[a]) * inv_d[a];
}

/* What the march needs of the ray, made once per ray and shared by both
 * levels of grid (a sub-grid has its parent's scale, so the same rounding
 * bounds). */
typedef struct {
    real p[3], d[3];
    real inv_d[3];      /* 1 / d_a; 0 where d_a is +0, -0 or so small that 1 / d_a overflows */
    bool parallel[3];   /* those axes: the ray never crosses a boundary of theirs */
    real slack[3];      /* the rounding of a computed crossing of axis a, in t; 0 where inv_d_a = 0 */
    real reach, d_max;
    long octant;        /* the octant of d, as g->empty counts it (an axis the ray never crosses may take either) */
    int step[3];        /* +1 or -1: the sign of d_a; 0 on the axes the ray never crosses */
    int ahead[3];       /* 1 when step_a > 0, else 0: a cell's far boundary along a is plane i_a + ahead_a */
} ray_frame;

/* snippet: dda_step */
/* Leaves the current cell through its boundary of axis a (the nearest one):
 * returns false when that boundary is the grid's own, true after moving to
 * the neighbour. */
static inline bool dda_step(const fast_grid *g, dda *m, int a, const ray_frame *rf)
{
    /* one step of the 3D-DDA along axis a.
     *     i_a = i_a + step_a                      (the neighbour across the boundary)
     *     outside 0 .. n_a - 1: return false      (the ray leaves the grid)
     *     cell = cell + step_a stride_a           (move_a; stride: 1, n_x, n_x n_y for x, y, z)
     *     next_a = t of the neighbour's far boundary along a:
     *              plane i_a + 1 when step_a > 0, plane i_a when step_a < 0
     *              (plane i_a + ahead_a; crossing(g, a, plane, p, inv_d) computes it)
     * Compute next_a from the plane each time rather than adding a fixed
     * t step: the sum would gather one rounding per cell. */
    m->i[a] += rf->step[a];
    if ((unsigned)m->i[a] >= (unsigned)g->n[a])
        return false;
    m->cell += m->move[a];
    m->next[a] = crossing(g, a, m->i[a] + rf->ahead[a], rf->p, rf->inv_d);
    return true;
}
/* end snippet */

/* The axis whose boundary the ray crosses first: the cell's far side.  x
 * when it is strictly first; else y when it is before z and x is not before
 * it; else z.  In arithmetic on the comparisons, without branches (which way
 * they go changes from cell to cell, and a mispredicted branch costs more)
 * and without a table (whose load would lengthen every step's chain): the
 * two cases exclude each other. */
static inline int nearest_axis(const dda *m)
{
    const real x = m->next[0], y = m->next[1], z = m->next[2];
    const int x_first = (x < y) & (x < z), y_first = (y < z) & !(x < y);
    return 2 - y_first - 2 * x_first;
}

/* The cell index along axis a of coordinate f (in cells from the grid's low
 * corner), clamped to lowest .. highest. */
static inline int index_in(real f, int lowest, int highest)
{
    /* without branches, as in nearest_axis: clamped, then truncated; the
     * upper bound is highest + 1/2 (which truncates to highest), so that the
     * compiler cannot turn the clamp into a branch that returns highest.  In
     * float, highest + 1/2 rounds to highest + 1 from 2^23 on: the last
     * clamp, in integers, keeps the index in range there. */
    real low = (real)lowest, high = (real)highest + (real)0.5;
    f = f > low ? f : low; /* also NaN; `>`, not `>=`, is the one instruction maxsd */
    f = f < high ? f : high;
    const int i = (int)f;
    return i < highest ? i : highest;
}

static inline int first_cell(const fast_grid *g, int a, real f) { return index_in(f, 0, g->n[a] - 1); }

/* snippet: leap */
/* The ray is in an empty cell c, and the cube of side `side` >= 2 that has c
 * as its corner and lies ahead of the ray (in the octant of its direction)
 * holds nothing.  Leave the cube in one step: along the axis whose far face
 * of the cube the ray crosses first, the new index is just past that face,
 * exactly; along the others it is the cell of the exit point, moved back
 * along the ray by its rounding (at0, per_t, back_per_t: enter's) and kept
 * inside the cube and the grid, so that rounding can only land the ray a
 * cell short (in the empty cube), never a cell too far.  False when the ray
 * leaves the grid through the cube's face. */
static inline bool dda_leap(const fast_grid *g, dda *m, int side, const ray_frame *rf)
{
    const int *step = rf->step, *ahead = rf->ahead;
    const real *p = rf->p, *inv_d = rf->inv_d;
    /* The t at which the ray crosses the cube's far face along each axis
     * (infinity on an axis it never crosses); the first of them is the exit. */
    real t_face[3];
    int far_end[3]; /* the index of the cube's last cell along each axis, the cell before its far face */
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        far_end[a] = step[a] > 0 ? m->i[a] + (side - 1) : m->i[a] - (side - 1); /* no product on the leaps' chain */
        t_face[a] = step[a] ? crossing(g, a, far_end[a] + ahead[a], p, inv_d) : REAL_INFINITY;
    }
    const int axis = t_face[0] <= t_face[1] ? (t_face[0] <= t_face[2] ? 0 : 2) : (t_face[1] <= t_face[2] ? 1 : 2);
    /* t_face[axis] and the index past the face by selects: indexed by axis, both arrays stay in memory */
    const real t_exit = axis == 0 ? t_face[0] : axis == 1 ? t_face[1] : t_face[2];
    if (!(t_exit < REAL_INFINITY)) /* no face ahead (or NaN): nothing to leap to */
        return false;
    const int beyond = axis == 0 ? far_end[0] + step[0] : axis == 1 ? far_end[1] + step[1] : far_end[2] + step[2];
    if (beyond < 0 || beyond >= g->n[axis])
        return false; /* the cube's face is beyond the grid's */
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        if (a == axis) {
            m->i[a] = beyond;
        } else if (step[a]) { /* in the cube and in the grid */
            real f = t_exit >= 0 ? m->at0[a] + t_exit * m->ahead_per_t[a]
                                 : m->at0[a] + t_exit * m->per_t[a] - real_abs(t_exit) * m->back_per_t[a];
            int lowest = step[a] > 0 ? m->i[a] : far_end[a] > 0 ? far_end[a] : 0;
            int highest = step[a] < 0 ? m->i[a] : far_end[a] < g->n[a] - 1 ? far_end[a] : g->n[a] - 1;
            m->i[a] = index_in(f, lowest, highest);
        } else {
            continue; /* the ray stays in its slab of cells along a */
        }
        m->next[a] = crossing(g, a, m->i[a] + ahead[a], p, inv_d);
    }
    m->cell = m->i[0] + g->stride[1] * m->i[1] + g->stride[2] * m->i[2];
    return true;
}
/* end snippet */


/* The largest |v_a|, for the rounding bounds, in selects (maxsd) where
 * vec3_max_abs branches: which component is largest changes from ray to ray
 * (bench-grid's random rays: 2 of 16 mispredicted branches a ray fewer).  A NaN
 * component may be passed over or kept: such a ray hits nothing, and its
 * march ends all the same. */
static inline real largest_abs(const real v[3])
{
    const real x = real_abs(v[0]), y = real_abs(v[1]), z = real_abs(v[2]);
    const real m = x > y ? x : y;
    return m > z ? m : z;
}

/* snippet: enter */
/* Rounding moves computed crossings by up to a few REAL_EPSILON times the
 * coordinates involved; `slack` bounds that in t per axis, and the march
 * errs towards visiting a cell too many, never one too few.  A component
 * d_a of +0 or -0 (or so small that 1/d_a overflows) never crosses a
 * boundary of its axis: the ray stays in one slab, or misses the box. */
static inline void frame_of(ray_frame *f, const fast_grid *g, ray r)
{
    /* in locals first, stored once at the end: the compiler cannot keep
     * fields of *f in registers across the stores into it */
    const real p[3] = {r.p.x, r.p.y, r.p.z}, d[3] = {r.d.x, r.d.y, r.d.z};
    const real reach = 16 * REAL_EPSILON * (largest_abs(p) + g->scale);
    real inv_d[3];
    long octant = 0;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        inv_d[a] = 1 / d[a];
        f->parallel[a] = !isfinite(inv_d[a]); /* d_a = +0 or -0, or tiny */
        inv_d[a] = f->parallel[a] ? 0 : inv_d[a];
        f->p[a] = p[a];
        f->d[a] = d[a];
        f->inv_d[a] = inv_d[a];
        f->slack[a] = reach * real_abs(inv_d[a]);
        f->step[a] = (inv_d[a] > 0) - (inv_d[a] < 0);
        f->ahead[a] = inv_d[a] > 0;
        octant |= (long)(inv_d[a] < 0) << a;
    }
    f->reach = reach;
    f->d_max = largest_abs(d);
    f->octant = octant;
}

/* Whether the ray meets the grid's box, the slabs lo_a <= p_a + t d_a <= hi_a
 * of the three axes, within (t_min, upper): *t0 is where it enters it. */
static inline bool box_window(const fast_grid *g, const ray_frame *f, real t_min, real upper, real *t0)
{
    const real *lo = g->lo_a, *hi = g->hi_a;
    real t1 = upper;
    *t0 = t_min;
    /* A ray from inside the box with the window (0, upper), as shadow rays
     * are: every slab's near side is at t <= 0 and its far side at t >= 0, so
     * the loop below would leave t0 = 0 <= t1.  It is skipped. */
    if (t_min == 0 && upper >= 0 && f->p[0] >= lo[0] && f->p[0] <= hi[0] && f->p[1] >= lo[1] && f->p[1] <= hi[1] &&
        f->p[2] >= lo[2] && f->p[2] <= hi[2])
        return true;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        if (f->parallel[a]) {
            if (!(f->p[a] >= lo[a] && f->p[a] <= hi[a]))
                return false;
            continue;
        }
        real near = (lo[a] - f->p[a]) * f->inv_d[a], far = (hi[a] - f->p[a]) * f->inv_d[a];
        if (near > far) {
            real swap = near;
            near = far;
            far = swap;
        }
        near -= f->slack[a];
        far += f->slack[a];
        *t0 = near > *t0 ? near : *t0; /* fmax and fmin, inline; a NaN is passed over as they do */
        t1 = far < t1 ? far : t1;
    }
    return *t0 <= t1; /* false: it misses the box, or the window ends before it */
}

/* Where the ray enters the grid's box within (t_min, upper) (box_window),
 * and the first cell: the one holding p + t0 d, moved back along the ray by
 * the rounding of that point, and clamped to the grid.  False when the ray
 * misses the box there. */
static inline bool enter(const fast_grid *g, const ray_frame *f, real t_min, real upper, dda *m)
{
    const real *lo = g->lo_a;
    real t0;
    if (!box_window(g, f, t_min, upper, &t0))
        return false;
    const real back = f->reach + 16 * REAL_EPSILON * real_abs(t0) * f->d_max;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        m->move[a] = f->step[a] * g->stride[a];
        m->at0[a] = (f->p[a] - lo[a] - (real)f->step[a] * f->reach) * g->inv_cell_a[a];
        m->per_t[a] = f->d[a] * g->inv_cell_a[a];
        m->back_per_t[a] = (real)f->step[a] * (16 * REAL_EPSILON * f->d_max) * g->inv_cell_a[a];
        m->ahead_per_t[a] = m->per_t[a] - m->back_per_t[a];
        real x = f->inv_d[a] != 0 ? f->p[a] + t0 * f->d[a] : f->p[a];
        m->i[a] = first_cell(g, a, (x - lo[a] - (real)f->step[a] * back) * g->inv_cell_a[a]);
        m->next[a] = f->step[a] ? crossing(g, a, m->i[a] + f->ahead[a], f->p, f->inv_d) : REAL_INFINITY;
    }
    m->cell = m->i[0] + g->stride[1] * m->i[1] + g->stride[2] * m->i[2];
    return true;
}
/* end snippet */

/* Asks the processor to fetch what a test of surface k reads (its kind and
 * a triangle's vertices: the lines of their first and last bytes, 80 bytes
 * that span at most two lines of 64 where a surface starts on 16 bytes)
 * while the march goes on with the cell's other entries. */
static inline void prefetch_surface(const surface_list *list, uint32_t k)
{
    /* a box's entry: some surface, never beyond the list */
    const surface *item = &list->items[k & (FAST_GRID_BOX - 1)];
    __builtin_prefetch(item);
    __builtin_prefetch((const char *)(&item->triangle.c + 1) - 1);
}

static void march(const fast_grid *g, search *s, const ray_frame *rf, march_state *ms);

/* snippet: cell */
/* Every surface of cell m->cell, each tested over the whole window
 * (t_min, best): a hit beyond this cell is kept too, and counts once the
 * march reaches its cell.  A cell of SIFT_FROM entries or more goes in
 * batches of up to BATCH entries: first the entries whose boxes are not
 * beside the ray's span, all the batch's boxes at once (box_near_span
 * without branches, which the compiler's vectoriser runs four entries to an
 * instruction), a bit each; then, of those, the ones not tested already
 * along the ray whose boxes the ray passes through (passes_box), gathered
 * without a branch on the test (which entries pass is different in every
 * cell: a branch on it is often guessed wrong); then each of those is
 * tested, after a second look at its box if a hit in the batch has closed
 * the window since.  A cell of fewer entries tests them one by one without
 * culling: most are large surfaces (a floor's triangles are listed in every
 * cell under it), culled again in every cell until tested once, where a
 * test settles them for the rest of the ray.  A cell with a grid of its own
 * (two levels) lists that grid first: the ray marches through it, then
 * takes the cell's other entries, the surfaces that span the cell. */
static inline void visit_cell(const fast_grid *g, const dda *m, cull_frame *f, search *s, const ray_frame *rf,
                              march_state *ms)
{
    const uint32_t first = g->start[m->cell], n = g->start[m->cell + 1] - first;
    if (n == 0)
        return;
    /* the cell's block: its surfaces, its boxes' low sides, their high sides (fast_grid.h) */
    const uint32_t *const surface = g->lists + 3 * (size_t)first, *const lo = surface + n, *const hi = lo + n;
    uint32_t j = 0;
    if (surface[0] >= FAST_GRID_SUB) {
        march(&g->subs[surface[0] - FAST_GRID_SUB], s, rf, ms);
        if (++j == n)
            return; /* no surface spans the cell beside its grid */
    }
    const bool cull = g->cull, use_mailbox = g->mailbox;
    if (!cull || n - j < SIFT_FROM) {
        if (ms->prefetch)
            for (uint32_t e = j; e < n; e++)
                prefetch_surface(s->list, surface[e]);
        test_entries(s, ms, g, surface + j, lo + j, hi + j, n - j, f, m->i, rf->p, rf->d, rf->inv_d, rf->slack);
        return;
    }
    uint32_t span_lo, span_hi;
    if (!f->started)
        cull_start(f, g, rf->d, rf->inv_d);
    cull_cell(f, g, m->i, rf->p, rf->inv_d, rf->slack);
    cull_span(f, g, m->i, rf->p, rf->d, rf->reach, rf->d_max, s->t_min, s->upper, &span_lo, &span_hi);
    /* bit k of a batch's mask stands for its entry k (SSE2 has no shift by a count per lane: a table) */
    static const uint32_t bit[BATCH] = {
        1u << 0,  1u << 1,  1u << 2,  1u << 3,  1u << 4,  1u << 5,  1u << 6,  1u << 7,  1u << 8,  1u << 9,  1u << 10,
        1u << 11, 1u << 12, 1u << 13, 1u << 14, 1u << 15, 1u << 16, 1u << 17, 1u << 18, 1u << 19, 1u << 20, 1u << 21,
        1u << 22, 1u << 23, 1u << 24, 1u << 25, 1u << 26, 1u << 27, 1u << 28, 1u << 29, 1u << 30, 1u << 31};
    for (; j < n;) {
        const uint32_t end = n - j > BATCH ? j + BATCH : n;
        const int batch = (int)(end - j);
        /* through pointers to the batch: indexed lo[j + k], an unsigned sum that may wrap, the loads
         * are not consecutive to the vectoriser */
        const uint32_t *const batch_lo = lo + j, *const batch_hi = hi + j;
        uint32_t near = 0; /* the entries whose boxes are not beside the span */
#pragma omp simd reduction(| : near)
        for (int k = 0; k < batch; k++)
            near |= bit[k] & box_near_span(batch_lo[k], batch_hi[k], span_lo, span_hi);
        uint32_t to_test[BATCH], n_near = 0, n_test = 0;
        const real upper = s->upper;
        for (; near; near &= near - 1) {
            const uint32_t e = j + (uint32_t)__builtin_ctz(near);
            n_near++;
            if (ms->prefetch) /* here, not in a loop of its own: one loop's end fewer to guess */
                prefetch_surface(s->list, surface[e]);
            if (tested_already(ms, use_mailbox, surface[e]))
                continue;
            const bool passes = passes_box(unpack_box(lo[e], hi[e]).side, f, s->t_min, s->upper);
            to_test[n_test] = e;
            n_test += passes;
            ms->culled += !passes;
        }
        ms->culled += (uint32_t)batch - n_near;
        for (uint32_t k = 0; k < n_test; k++) {
            const uint32_t e = to_test[k];
            if (s->upper != upper && !passes_box(unpack_box(lo[e], hi[e]).side, f, s->t_min, s->upper)) {
                ms->culled++; /* a hit in this batch has closed the window before its box */
                continue;
            }
            test_noted(s, ms, g, rf->p, rf->inv_d, rf->slack, use_mailbox, surface[e]);
        }
        j = end;
    }
}
/* end snippet */

/* snippet: march */
/* The march through grid g (the top grid, or a cell's own), from where the
 * ray enters its box within the window to where it leaves it or the search
 * is settled. */
static void march(const fast_grid *g, search *s, const ray_frame *rf, march_state *ms)
{
    dda m;
    if (g->n_cells == 0 || !enter(g, rf, s->t_min, s->upper, &m))
        return;
    cull_frame f;
    f.started = false;
    const uint8_t *empty = g->empty ? g->empty + rf->octant * g->n_cells : NULL; /* the ray's octant's */
    for (;;) {
        ms->cells++;
        /* The cell ends where the ray crosses its nearest boundary, along axis a. */
        const int a = nearest_axis(&m);
        if (ms->prefetch && (unsigned)(m.i[a] + rf->step[a]) < (unsigned)g->n[a]) {
            /* the neighbour across it: its list's start and its empty cubes, fetched during this visit */
            const long next = m.cell + m.move[a];
            __builtin_prefetch(&g->start[next]);
            if (empty)
                __builtin_prefetch(&empty[next]);
        }
        /* the cube of empty cells ahead (0: the cell lists surfaces; with no leap table, visit every cell) */
        const int side = empty ? empty[m.cell] : 0;
        if (side == 0) /* read the cell's list only then: an empty cell's may be a cache miss */
            visit_cell(g, &m, &f, s, rf, ms);
        /* A hit no farther than that boundary is the closest: every surface
         * before it along the ray lies in this cell or an earlier one, all
         * tested.  A hit beyond it may yet lose to a surface of a later cell:
         * march on. */
        if (s->best_t <= m.next[a] - rf->slack[a])
            return;
        if (side >= 2) { /* a cube of empty cells ahead: leap over it */
            ms->leaps++;
            if (!dda_leap(g, &m, side, rf))
                return;
            if (ms->prefetch) /* the list's start of the cell it lands in, fetched while its leap table is read */
                __builtin_prefetch(&g->start[m.cell]);
            continue;
        }
        if (!dda_step(g, &m, a, rf))
            return;
    }
}
/* end snippet */

/* Whether the ray has a component d_a != 0 so small that 1 / d_a overflows:
 * the march takes it as 0 (it stays in its slab of cells: frame_of's
 * limit), but a list need not: its units are tested whatever the box says. */
static inline bool moves_unseen(const ray_frame *rf)
{
    return (rf->parallel[0] && rf->d[0] != 0) | (rf->parallel[1] && rf->d[1] != 0) | (rf->parallel[2] && rf->d[2] != 0);
}

/* The search of ray r through g, to its end: the best hit is s->best (-1: none). */
static inline void search_grid(const fast_grid *g, search *s, ray r, real t_min, real t_max, fast_grid_counts *counts)
{
    search_start(s, g->list, r, t_min, t_max);
    for (long u = 0; u < g->n_unbinned; u++)
        test_surface(s, g->unbinned[u]);
    march_state ms;
    ms.cells = ms.leaps = ms.culled = 0;
    ms.prefetch = g->prefetch;
    ms.spheres = g->cull && g->spheres && g->list->sphere_formula == SPHERE_ROBUST; /* (fast_noted.h) */
    if (g->n_cells || g->units) {
        ray_frame rf;
        frame_of(&rf, g, r);
        noted_start(&ms, g);
        real t0;
        if (!vec3_is_finite(r.p)) { /* its rounding slack is not finite, nor are its crossings: no march */
            for (int k = 0; k < g->list->n; k++)
                test_surface(s, (uint32_t)k);
        } else if (!g->units) { /* the large surfaces apart first: a hit on them can end the march early */
            for (long u = 0; u < g->n_apart; u++)
                test_noted(s, &ms, g, rf.p, rf.inv_d, rf.slack, false, g->apart[u]);
            march(g, s, &rf, &ms);
        } else if (moves_unseen(&rf) || box_window(g, &rf, s->t_min, s->upper, &t0)) { /* a list: each once */
            for (long u = 0; u < g->n_units; u++)
                test_noted(s, &ms, g, rf.p, rf.inv_d, rf.slack, false, g->units[u]);
        }
    }
    if (counts) {
        counts->cells += ms.cells;
        counts->leaps += ms.leaps;
        counts->tests += s->tests;
        counts->culled += ms.culled;
    }
}

bool fast_grid_intersect_counted(const fast_grid *g, ray r, real t_min, real t_max, hit_record *hit,
                                 fast_grid_counts *counts)
{
    search s;
    search_grid(g, &s, r, t_min, t_max, counts);
    if (s.best < 0)
        return false;
    *hit = search_record(&s, g->normal);
    return true;
}

bool fast_grid_intersect(const fast_grid *g, ray r, real t_min, real t_max, hit_record *hit)
{
    return fast_grid_intersect_counted(g, r, t_min, t_max, hit, NULL);
}

bool fast_grid_closest(const fast_grid *g, ray r, real t_min, real t_max, fast_grid_hit *hit)
{
    search s;
    search_grid(g, &s, r, t_min, t_max, NULL);
    if (s.best < 0)
        return false;
    hit->surface = s.best;
    hit->t = s.best_t;
    hit->beta = s.recorded ? s.hit.beta : s.tri.beta;
    hit->gamma = s.recorded ? s.hit.gamma : s.tri.gamma;
    return true;
}
