/* fast_cull.h - chapter 11's lab: culling, the test of a ray against the part of a surface's box in a cell.
 *
 * Each entry of a cell's list carries the part of its surface's box inside
 * the cell, in bytes (fast_build.c's cull_box).  Once per cell the march
 * computes the span of the ray in the same units (cull_span); a box beside
 * that span is passed by with a test on two words (box_near_span, four
 * entries at once), and the few left get the slab test (passes_box) before
 * the surface test.  Their loops over the three axes are unrolled as
 * fast_march.c's are, all but cull_start's: unrolled, it makes gcc warn
 * that the fields it sets may be read unset (-Wmaybe-uninitialized, which
 * does not follow `started`).
 */
#ifndef CH11_LAB_FAST_CULL_H
#define CH11_LAB_FAST_CULL_H

#include <string.h>

#include "11_grid/lab/fast_grid.h"

/* cull_span's clamps, -1/2, FAST_GRID_BOX_STEPS + 1/2 and FAST_GRID_BOX_STEPS - 1/2,
 * defined in fast_cull.c (there: why). */
extern const real fast_cull_span_clamp[3];

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
    real near_top[3], far_top[3]; /* 0 or FAST_GRID_BOX_STEPS unit_a: the frame's own sides, near and far */
    bool started;                 /* cull_start has filled in the fields above */
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

/* What the cull frame of every cell of g has for the ray with direction d
 * (inv_d as the march has it): the steps' length in t and the sides the
 * ray enters and leaves by.  Once per grid and ray, at the first cell that
 * culls (many rays meet none). */
static inline void cull_start(cull_frame *f, const fast_grid *g, const real d[3], const real inv_d[3])
{
    for (int a = 0; a < 3; a++) {
        f->unit[a] = g->frame_step[a] * inv_d[a];
        f->near[a] = d[a] < 0 ? 3 + a : a;
        f->far[a] = d[a] < 0 ? a : 3 + a;
        f->near_top[a] = (d[a] < 0 ? FAST_GRID_BOX_STEPS : 0) * f->unit[a];
        f->far_top[a] = (d[a] < 0 ? 0 : FAST_GRID_BOX_STEPS) * f->unit[a];
    }
    f->started = true;
}

/* The cull frame of cell i: its base_a, widened by the march's slack_a
 * (infinite where inv_d_a = 0: every box then passes), for passes_box. */
static inline void cull_cell(cull_frame *f, const fast_grid *g, const int i[3], const real p[3], const real inv_d[3],
                             const real slack[3])
{
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        real base = inv_d[a] != 0 ? (g->plane[a][i[a]] - g->margin - p[a]) * inv_d[a] : 0;
        real widen = inv_d[a] != 0 ? slack[a] : REAL_INFINITY;
        f->enter[a] = base - widen;
        f->leave[a] = base + widen;
    }
}

/* The span of the ray in cell i, whose frame cull_cell made: along each
 * axis, the steps of the frame that the ray's points at t in (t_min, upper)
 * inside the frame cover, widened by one step and by the rounding of those
 * points, lo_a .. hi_a, clamped to 0 .. FAST_GRID_BOX_STEPS.  A box that
 * ends before the span or starts after it, along any axis, is passed by: a
 * cheaper test in integers that settles most boxes before passes_box.  A
 * NaN leaves the span whole.  The span is returned packed for
 * box_near_span, as the lists pack the boxes: lo_a in byte a of *span_lo,
 * hi_a in byte a of *span_hi.  It costs as much as a few passes_box: the
 * march computes it only for a cell that lists many surfaces. */
static inline void cull_span(const cull_frame *f, const fast_grid *g, const int i[3], const real p[3], const real d[3],
                             real reach, real d_max, real t_min, real upper, uint32_t *span_lo, uint32_t *span_hi)
{
    real t_in = t_min, t_out = upper, origin[3];
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        origin[a] = g->plane[a][i[a]] - g->margin;
        real t0 = f->enter[a] + f->near_top[a];
        real t1 = f->leave[a] + f->far_top[a];
        t_in = t0 > t_in ? t0 : t_in;
        t_out = t1 < t_out ? t1 : t_out;
    }
    const real t_abs = real_abs(t_in) > real_abs(t_out) ? real_abs(t_in) : real_abs(t_out);
    const real rounding = reach + 16 * REAL_EPSILON * t_abs * d_max;
    uint32_t packed_lo = 0, packed_hi = 0;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        real per_unit = g->per_unit[a];
        real q0 = (p[a] + t_in * d[a] - origin[a]) * per_unit, q1 = (p[a] + t_out * d[a] - origin[a]) * per_unit;
        real widen = 1 + rounding * per_unit;
        real q_lo = (q0 < q1 ? q0 : q1) - widen, q_hi = (q0 < q1 ? q1 : q0) + widen;
        /* lo_a: q_lo truncated, in 0 .. FAST_GRID_BOX_STEPS (a NaN: 0); hi_a: q_hi truncated plus
         * one, in 0 .. FAST_GRID_BOX_STEPS (0 when q_hi <= 0; a NaN: FAST_GRID_BOX_STEPS).  Clamped
         * without branches (whether a side is clamped changes from cell to cell), to half a step
         * beyond the ends, which truncates to the ends. */
        const real below = fast_cull_span_clamp[0], beyond = fast_cull_span_clamp[1], last = fast_cull_span_clamp[2];
        real lo_c = q_lo > below ? q_lo : below; /* also NaN */
        lo_c = lo_c < beyond ? lo_c : beyond;
        real hi_c = q_hi < last ? q_hi : last; /* also NaN */
        const int above = hi_c > 0;
        hi_c = hi_c > below ? hi_c : below;
        const int span_a_lo = (int)lo_c, span_a_hi = ((int)hi_c + 1) & -above;
        packed_lo |= (uint32_t)span_a_lo << (8 * a);
        packed_hi |= (uint32_t)span_a_hi << (8 * a);
    }
    *span_lo = packed_lo;
    *span_hi = packed_hi;
}

/* All ones when an entry's box is not beside the span along any axis, else
 * zero: its high side at or above the span's low end (hi_a >= lo_a) and its
 * low side at or below the span's high end, for the three axes at once
 * ("SIMD within a register"): with x and y bytes of 0 .. 127, byte (x | 128)
 * - y keeps its top bit exactly when x >= y, and never borrows from the next
 * byte.  The box comes as the lists pack it (fast_pack.c): its low sides in
 * bytes 0-2 of `lo`, its high sides in those of `hi`.  No branch, so that
 * the march's loop over a cell's boxes runs four of them at once. */
static inline uint32_t box_near_span(uint32_t lo, uint32_t hi, uint32_t span_lo, uint32_t span_hi)
{
    const uint32_t tops = 0x808080u;
    const uint32_t both = ((hi | tops) - span_lo) & ((span_hi | tops) - lo) & tops;
    return 0u - (uint32_t)(both == tops);
}

/* An entry's box as cull_box wrote it (lo x, y, z, hi x, y, z, two zeros),
 * for passes_box, from its two packed words: their value lo | hi << 24 in
 * memory, which is those bytes in that order on a little-endian processor,
 * and reversed on a big-endian one. */
typedef struct {
    uint8_t side[8];
} box_sides;

static inline box_sides unpack_box(uint32_t lo, uint32_t hi)
{
    const uint64_t value = lo | (uint64_t)hi << 24;
    const uint16_t one = 1;
    uint8_t first;
    memcpy(&first, &one, 1); /* 1 on a little-endian processor (a test the compiler settles) */
    box_sides b;
    memcpy(b.side, &value, sizeof value);
    for (int k = 0; k < 4 && first != 1; k++) {
        const uint8_t swap = b.side[k];
        b.side[k] = b.side[7 - k];
        b.side[7 - k] = swap;
    }
    return b;
}

#endif
