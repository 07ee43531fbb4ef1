/* fast_march.c - chapter 11's lab: the fast grid's march: culling, mailbox, leaps, batches. */
#include "11_grid/lab/fast_grid.h"

#include <math.h>

#include "03_triangle/watertight.h"

#ifdef RT_REAL_FLOAT
#define real_next_up(x) nextafterf((x), INFINITY)
#else
#define real_next_up(x) nextafter((x), INFINITY)
#endif

/* The mailbox: the last surfaces tested along this ray, one slot per value
 * of (index mod MAILBOX).  A surface found in its slot was tested already
 * and is skipped; a slot taken over by another surface only costs a second
 * test of the first, never a wrong answer. */
#define MAILBOX 32

/* A cell's entries are sifted this many at a time. */
#define BATCH 32

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

/* The search for ray r in (t_min, t_max). */
static search search_start(const surface_list *list, ray r, real t_min, real t_max)
{
    return (search){.list = list, .r = r, .t_min = t_min, .best_t = t_max, .upper = t_max, .best = -1,
                    .by_ray = list->triangle_test == TRIANGLE_WATERTIGHT ? -1 : 0};
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

/* The new best hit: surface k at t. */
static inline void take(search *s, uint32_t k, real t)
{
    s->best_t = t;
    s->upper = real_next_up(t);
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

/* The best hit's record, as surface_intersect would have filled it in. */
static hit_record search_record(const search *s)
{
    hit_record h = s->hit;
    if (!s->recorded) {
        const surface *item = &s->list->items[s->best];
        h = surface_hit_record(item, s->r, s->best_t, triangle_normal(&item->triangle), s->tri.beta, s->tri.gamma);
    }
    h.surface = s->best;
    return h;
}

/* snippet: cull */
/* Whether the ray can meet the part of a surface's box inside the cell,
 * `box` (cull_box: steps of the cell's frame), at some t in (t_min, upper):
 * the slabs of the three axes overlap there.  Along axis a the frame's low
 * side is crossed at base_a and each step adds unit_a, so side q is crossed
 * at base_a + q unit_a; the side the ray enters by is box[near_a] (box[a]
 * for d_a > 0, box[3 + a] for d_a < 0) and it leaves by box[far_a].  Each
 * crossing is widened by the axis's rounding slack: enter[a] = base_a -
 * slack_a, leave[a] = base_a + slack_a.  A NaN never culls, so that a
 * surface surface_intersect would report is never culled.  Written out
 * axis by axis: it runs for every surface of every cell the ray visits. */
typedef struct {
    real enter[3], leave[3], unit[3];
    int near[3], far[3];
} cull_frame;

static inline bool passes_box(const uint8_t box[8], const cull_frame *f, real t_min, real upper)
{
    real x0 = f->enter[0] + (real)box[f->near[0]] * f->unit[0], x1 = f->leave[0] + (real)box[f->far[0]] * f->unit[0];
    real y0 = f->enter[1] + (real)box[f->near[1]] * f->unit[1], y1 = f->leave[1] + (real)box[f->far[1]] * f->unit[1];
    real z0 = f->enter[2] + (real)box[f->near[2]] * f->unit[2], z1 = f->leave[2] + (real)box[f->far[2]] * f->unit[2];
    real t_in = x0 > t_min ? x0 : t_min, t_out = x1 < upper ? x1 : upper;
    t_in = y0 > t_in ? y0 : t_in;
    t_out = y1 < t_out ? y1 : t_out;
    t_in = z0 > t_in ? z0 : t_in;
    t_out = z1 < t_out ? z1 : t_out;
    return !(t_in > t_out);
}
/* end snippet */

/* The cull frame of cell i (its base_a), and the span of the ray in it:
 * along each axis, the steps of the frame that the ray's points at t in
 * (t_min, upper) inside the frame cover, widened by one step and by the
 * rounding of those points, lo_a .. hi_a, clamped to 0 .. FAST_GRID_BOX_STEPS.
 * A box that ends before the span or starts after it, along any axis, is
 * passed by: a cheaper test in integers that settles most boxes before
 * passes_box.  A NaN leaves the span whole.  The span is returned packed
 * for box_beside_span: hi_a in byte a of *span_hi, lo_a in byte 3 + a of
 * *span_lo. */
static inline void cull_span(cull_frame *f, const fast_grid *g, const int i[3], const real p[3], const real d[3],
                             const real inv_d[3], const real cull_slack[3], real reach, real d_max, real t_min,
                             real upper, uint64_t *span_lo, uint64_t *span_hi)
{
    const real top = FAST_GRID_BOX_STEPS;
    real t_in = t_min, t_out = upper, origin[3];
    for (int a = 0; a < 3; a++) {
        origin[a] = g->plane[a][i[a]] - g->margin;
        real base = inv_d[a] != 0 ? (origin[a] - p[a]) * inv_d[a] : 0;
        f->enter[a] = base - cull_slack[a];
        f->leave[a] = base + cull_slack[a];
        real t0 = f->enter[a] + (f->near[a] < 3 ? 0 : top) * f->unit[a];
        real t1 = f->leave[a] + (f->far[a] < 3 ? 0 : top) * f->unit[a];
        t_in = t0 > t_in ? t0 : t_in;
        t_out = t1 < t_out ? t1 : t_out;
    }
    const real t_abs = real_abs(t_in) > real_abs(t_out) ? real_abs(t_in) : real_abs(t_out);
    const real rounding = reach + 16 * REAL_EPSILON * t_abs * d_max;
    uint64_t packed_lo = 0, packed_hi = 0;
    for (int a = 0; a < 3; a++) {
        real per_unit = g->per_unit[a];
        real q0 = (p[a] + t_in * d[a] - origin[a]) * per_unit, q1 = (p[a] + t_out * d[a] - origin[a]) * per_unit;
        real widen = 1 + rounding * per_unit;
        real q_lo = (q0 < q1 ? q0 : q1) - widen, q_hi = (q0 < q1 ? q1 : q0) + widen;
        int span_a_lo = q_lo > 0 && q_lo < top ? (int)q_lo : q_lo >= top ? FAST_GRID_BOX_STEPS : 0; /* NaN: 0 */
        int span_a_hi = q_hi < top - 1 && q_hi > 0 ? (int)q_hi + 1 : q_hi <= 0 ? 0 : FAST_GRID_BOX_STEPS; /* NaN: top */
        packed_lo |= (uint64_t)span_a_lo << (8 * (3 + a));
        packed_hi |= (uint64_t)span_a_hi << (8 * a);
    }
    *span_lo = packed_lo;
    *span_hi = packed_hi;
}

/* Whether the box of an entry lies beside the span along some axis: its
 * high side below the span's low end (hi_a < lo_a), or its low side above
 * the span's high end (box lo_a > span hi_a).  All six comparisons at once,
 * bytewise in one 64-bit word ("SIMD within a register"): with x and y
 * bytes of 0 .. 127, byte (x | 128) - y has its top bit set exactly when
 * x >= y, and never borrows from the next byte.  The box's bytes are lo_x,
 * lo_y, lo_z, hi_x, hi_y, hi_z: bytes 0-2 compare span hi >= box lo, bytes
 * 3-5 box hi >= span lo. */
static inline bool box_beside_span(const uint8_t box[8], uint64_t span_lo, uint64_t span_hi)
{
    const uint64_t low3 = 0xFFFFFFull, high3 = 0xFFFFFF000000ull, tops = 0x808080808080ull;
    /* byte k of the box in byte k of b: compilers make this one load */
    uint64_t b = (uint64_t)box[0] | (uint64_t)box[1] << 8 | (uint64_t)box[2] << 16 | (uint64_t)box[3] << 24 |
                 (uint64_t)box[4] << 32 | (uint64_t)box[5] << 40 | (uint64_t)box[6] << 48 | (uint64_t)box[7] << 56;
    uint64_t x = (b & high3) | span_hi, y = (b & low3) | span_lo;
    return (((x | tops) - y) & tops) != tops;
}

/* snippet: dda */
/* The march's state (Amanatides and Woo): the cell the ray is in, the
 * direction of its steps, and the t at which it crosses the next cell
 * boundary along each axis. */
typedef struct {
    int i[3];     /* the cell's indices */
    int step[3];  /* +1 or -1: the sign of d_a; 0 when d_a = 0 (the ray never crosses a boundary of that axis) */
    real next[3]; /* t of the next boundary crossing along each axis; +infinity when step is 0 */
    long cell;    /* i[0] + n_x (i[1] + n_y i[2]): the cell's place in g->start */
} dda;
/* end snippet */

/* t where the ray p + t d crosses plane `plane` (a cell boundary, counted
 * from the grid's low corner) of axis a: lo_a + plane cell_a = p_a + t d_a
 * (g->plane holds lo_a + plane cell_a). */
static inline real crossing(const fast_grid *g, int a, int plane, const real p[3], const real inv_d[3])
{
    return (g->plane[a][plane] - p[a]) * inv_d[a];
}

/* snippet: dda_step */
/* Leaves the current cell through its boundary of axis a (the nearest one):
 * returns false when that boundary is the grid's own, true after moving to
 * the neighbour. */
static inline bool dda_step(const fast_grid *g, dda *m, int a, const real p[3], const real inv_d[3])
{
    /* one step of the 3D-DDA along axis a.
     *     i_a = i_a + step_a                      (the neighbour across the boundary)
     *     outside 0 .. n_a - 1: return false      (the ray leaves the grid)
     *     cell = cell + step_a stride_a           (stride: 1, n_x, n_x n_y for x, y, z)
     *     next_a = t of the neighbour's far boundary along a:
     *              plane i_a + 1 when step_a > 0, plane i_a when step_a < 0
     *              (crossing(g, a, plane, p, inv_d) computes it)
     * Compute next_a from the plane each time rather than adding a fixed
     * t step: the sum would gather one rounding per cell. */
    const long stride[3] = {1, g->n[0], (long)g->n[0] * g->n[1]};
    m->i[a] += m->step[a];
    if ((unsigned)m->i[a] >= (unsigned)g->n[a])
        return false;
    m->cell += m->step[a] * stride[a];
    m->next[a] = crossing(g, a, m->i[a] + (m->step[a] > 0), p, inv_d);
    return true;
}
/* end snippet */

/* The axis whose boundary the ray crosses first: the cell's far side.  From
 * the three comparisons, without branches (which way they go changes from
 * cell to cell, and a mispredicted branch costs more than the lookup). */
static inline int nearest_axis(const dda *m)
{
    static const int8_t axis[8] = {2, 1, 2, 1, 2, 2, 0, 0}; /* by (x<y, x<z, y<z) */
    int k = ((m->next[0] < m->next[1]) << 2) | ((m->next[0] < m->next[2]) << 1) | (m->next[1] < m->next[2]);
    return axis[k];
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
    f = f >= low ? f : low; /* also NaN */
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
 * along the ray by the rounding of that point (`back`, in units of length)
 * and kept inside the cube and the grid, so that rounding can only land the
 * ray a cell short (in the empty cube), never a cell too far.  False when
 * the ray leaves the grid through the cube's face. */
static inline bool dda_leap(const fast_grid *g, dda *m, int side, const real p[3], const real d[3], const real inv_d[3],
                            real reach, real d_max)
{
    /* The t at which the ray crosses the cube's far face along each axis
     * (infinity on an axis it never crosses); the first of them is the exit. */
    real t_face[3];
    for (int a = 0; a < 3; a++)
        t_face[a] = m->step[a] ? crossing(g, a, m->i[a] + (m->step[a] > 0 ? side : 1 - side), p, inv_d) : REAL_INFINITY;
    const int axis = t_face[0] <= t_face[1] ? (t_face[0] <= t_face[2] ? 0 : 2) : (t_face[1] <= t_face[2] ? 1 : 2);
    const real t_exit = t_face[axis];
    if (!(t_exit < REAL_INFINITY)) /* no face ahead (or NaN): nothing to leap to */
        return false;
    const int beyond = m->i[axis] + m->step[axis] * side;
    if (beyond < 0 || beyond >= g->n[axis])
        return false; /* the cube's face is beyond the grid's */
    const real back = reach + 16 * REAL_EPSILON * real_abs(t_exit) * d_max;
    for (int a = 0; a < 3; a++) {
        if (a == axis) {
            m->i[a] = beyond;
        } else if (m->step[a]) { /* in the cube and in the grid */
            real f = (p[a] + t_exit * d[a] - g->lo_a[a] - (real)m->step[a] * back) * g->inv_cell_a[a];
            int far_end = m->i[a] + m->step[a] * (side - 1);
            int lowest = m->step[a] > 0 ? m->i[a] : far_end > 0 ? far_end : 0;
            int highest = m->step[a] < 0 ? m->i[a] : far_end < g->n[a] - 1 ? far_end : g->n[a] - 1;
            m->i[a] = index_in(f, lowest, highest);
        } else {
            continue; /* the ray stays in its slab of cells along a */
        }
        m->next[a] = crossing(g, a, m->i[a] + (m->step[a] > 0), p, inv_d);
    }
    m->cell = m->i[0] + (long)g->n[0] * (m->i[1] + (long)g->n[1] * m->i[2]);
    return true;
}
/* end snippet */

bool fast_grid_intersect_counted(const fast_grid *g, ray r, real t_min, real t_max, hit_record *hit, fast_grid_counts *counts)
{
    search s = search_start(g->list, r, t_min, t_max);
    uint64_t cells = 0, culled = 0;
    for (long u = 0; u < g->n_unbinned; u++)
        test_surface(&s, g->unbinned[u]);
    if (g->n_cells == 0)
        goto done;

    /* snippet: enter */
    /* Where the ray enters the grid's box: the slabs lo_a <= p_a + t d_a <= hi_a
     * of the three axes, within (t_min, t_max).  A component d_a of +0 or -0
     * (or so small that 1/d_a overflows) never crosses a boundary of its
     * axis: the ray stays in one slab, or misses the box.
     * Rounding moves computed crossings by up to a few REAL_EPSILON times the
     * coordinates involved; `slack` bounds that in t per axis, and the march
     * errs towards visiting a cell too many, never one too few. */
    const real p[3] = {r.p.x, r.p.y, r.p.z}, d[3] = {r.d.x, r.d.y, r.d.z};
    const real lo[3] = {g->lo.x, g->lo.y, g->lo.z}, hi[3] = {g->hi.x, g->hi.y, g->hi.z};
    const real reach = 16 * REAL_EPSILON * (vec3_max_abs(r.p) + g->scale);
    real inv_d[3], slack[3], t0 = t_min, t1 = t_max;
    int near[3], far[3];
    for (int a = 0; a < 3; a++) {
        inv_d[a] = 1 / d[a];
        near[a] = d[a] < 0 ? 3 + a : a;
        far[a] = d[a] < 0 ? a : 3 + a;
        if (!isfinite(inv_d[a])) { /* d_a = +0 or -0, or tiny */
            inv_d[a] = slack[a] = 0;
            if (!(p[a] >= lo[a] && p[a] <= hi[a]))
                goto done;
            continue;
        }
        slack[a] = reach * real_abs(inv_d[a]);
        real near = (lo[a] - p[a]) * inv_d[a], far = (hi[a] - p[a]) * inv_d[a];
        if (near > far) {
            real swap = near;
            near = far;
            far = swap;
        }
        near -= slack[a];
        far += slack[a];
        t0 = near > t0 ? near : t0; /* fmax and fmin, inline; a NaN is passed over as they do */
        t1 = far < t1 ? far : t1;
    }
    if (!(t0 <= t1)) /* misses the box, or the window ends before it */
        goto done;

    /* The first cell: the one holding p + t0 d, moved back along the ray by
     * the rounding of that point, and clamped to the grid. */
    dda m;
    const real d_max = vec3_max_abs(r.d);
    const real back = reach + 16 * REAL_EPSILON * real_abs(t0) * d_max;
    const real inv_cell[3] = {g->inv_cell.x, g->inv_cell.y, g->inv_cell.z};
    for (int a = 0; a < 3; a++) {
        m.step[a] = inv_d[a] > 0 ? 1 : inv_d[a] < 0 ? -1 : 0;
        real x = inv_d[a] != 0 ? p[a] + t0 * d[a] : p[a];
        m.i[a] = first_cell(g, a, (x - lo[a] - (real)m.step[a] * back) * inv_cell[a]);
        m.next[a] = m.step[a] ? crossing(g, a, m.i[a] + (m.step[a] > 0), p, inv_d) : REAL_INFINITY;
    }
    m.cell = m.i[0] + (long)g->n[0] * (m.i[1] + (long)g->n[1] * m.i[2]);
    /* the octant of d, as g->empty counts it (an axis the ray never crosses may take either) */
    const long octant = (m.step[0] < 0) | (m.step[1] < 0) << 1 | (m.step[2] < 0) << 2;
    /* end snippet */

    /* snippet: march */
    uint32_t mailbox[MAILBOX];
    for (int b = 0; b < MAILBOX; b++)
        mailbox[b] = UINT32_MAX;
    /* culling: the frame of a cell (the cell widened by the margin) along
     * axis a is crossed at base_a = (its low side - p_a) / d_a, and a step
     * of it adds unit_a; on an axis the ray is parallel to, both are 0 and
     * an infinite slack lets every box pass */
    cull_frame f = {.unit = {0}}; /* the rest is set before use */
    real cull_slack[3];
    for (int a = 0; a < 3; a++) {
        f.unit[a] = g->frame_step[a] * inv_d[a];
        f.near[a] = near[a];
        f.far[a] = far[a];
        cull_slack[a] = inv_d[a] != 0 ? slack[a] : REAL_INFINITY;
    }
    const fast_grid_entry *const refs = g->refs;
    const bool cull = g->cull;
    const bool use_mailbox = g->mailbox;
    for (;;) {
        /* Every surface of the cell, each tested over the whole window
         * (t_min, best): a hit beyond this cell is kept too, and counts once
         * the march reaches its cell. */
        cells++;
        const uint32_t first = g->start[m.cell], last = g->start[m.cell + 1];
        uint64_t span_lo = 0, span_hi = 0;
        if (cull && first < last)
            cull_span(&f, g, m.i, p, d, inv_d, cull_slack, reach, d_max, t_min, s.upper, &span_lo, &span_hi);
        /* In batches of up to BATCH entries: first the entries whose boxes
         * are not beside the ray's span, gathered without branches (which
         * entries pass is different in every cell: a branch on it is often
         * guessed wrong); then, of those, each one not tested
         * yet whose box the ray passes through is tested. */
        for (uint32_t e = first; e < last;) {
            const uint32_t end = last - e > BATCH ? e + BATCH : last, batch = end - e;
            const fast_grid_entry *near_ray[BATCH];
            uint32_t n_near = 0;
            for (; e < end; e++) {
                near_ray[n_near] = &refs[e];
                n_near += !cull | !box_beside_span(refs[e].box, span_lo, span_hi);
            }
            culled += batch - n_near;
            for (uint32_t j = 0; j < n_near; j++) {
                const uint32_t k = near_ray[j]->surface;
                if (use_mailbox && mailbox[k % MAILBOX] == k)
                    continue; /* tested already along this ray */
                if (cull && !passes_box(near_ray[j]->box, &f, t_min, s.upper)) {
                    culled++;
                    continue; /* the ray passes by its box in this cell */
                }
                if (use_mailbox)
                    mailbox[k % MAILBOX] = k;
                test_surface(&s, k);
            }
        }
        /* The cell ends where the ray crosses its nearest boundary.  A hit no
         * farther than that is the closest: every surface before it along the
         * ray lies in this cell or an earlier one, all tested.  A hit beyond
         * it may yet lose to a surface of a later cell: march on. */
        int a = nearest_axis(&m);
        if (s.best_t <= m.next[a] - slack[a])
            break;
        if (g->empty && g->empty[8 * m.cell + octant] >= 2) { /* a cube of empty cells ahead: leap over it */
            if (!dda_leap(g, &m, g->empty[8 * m.cell + octant], p, d, inv_d, reach, d_max))
                break;
            continue;
        }
        if (!dda_step(g, &m, a, p, inv_d))
            break;
    }
    /* end snippet */

done:
    if (counts) {
        counts->cells += cells;
        counts->tests += s.tests;
        counts->culled += culled;
    }
    if (s.best < 0)
        return false;
    *hit = search_record(&s);
    return true;
}

bool fast_grid_intersect(const fast_grid *g, ray r, real t_min, real t_max, hit_record *hit)
{
    return fast_grid_intersect_counted(g, r, t_min, t_max, hit, NULL);
}
