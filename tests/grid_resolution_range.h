/* grid_resolution_range.h - what chapter 11's README allows grid_resolution to answer, computed
 * another way than the reference's loop (for test_11_grid.c and tests/seeded/11_grid.c).
 *
 * The rule (README, "The grid's box and resolution"): at s cells per unit of length a spanned axis
 * gets round(e_a s) cells, clamped to 1 .. 2^20, a flat axis one.  The first try takes s0 for
 * max(1, min(lambda N, cap)) cells; when lambda N is within the cap and the product fits it, those
 * are the cells, exactly.  Otherwise s shrinks by a factor from 0.9 to 1 a try until the product
 * fits (from s0, or from the s of lambda N cells: both are allowed).  The product is a
 * non-decreasing step function of s, so the s that fit are those below s_fit, the least s whose
 * product is above the cap (none when no s is); every try before the last had a product above the
 * cap, so it was at least s_fit, and the last is at least 0.9 of it, or is the first try, at least
 * s0.  Any such rule answers, on every axis, a count from cells(0.9 min(s0, s_fit)) to
 * cells(s_fit), with a product at most the cap: with many cells on every axis that product is at
 * least about 0.9^k of the cap (0.73 for k = 3), with few less, since an axis rounds by up to half
 * a cell (the cap 7 over a box 1 x 1 x 1 gets 1 x 1 x 1: s_fit is 1.5, where the cells go from 1
 * to 8).  The bounds are taken a relative 1e-9 wider, for the rounding of e_a s: far more than a
 * few units of 2^-52, far less than the step (at least one cell in 2^20) by which a count changes. */
#ifndef RT_TESTS_GRID_RESOLUTION_RANGE_H
#define RT_TESTS_GRID_RESOLUTION_RANGE_H

#include <math.h>
#include <stdbool.h>

typedef struct {
    bool capped;               /* the first try's product is above the cap */
    int lowest[3], highest[3]; /* the counts allowed on each axis (equal when not capped) */
} grid_resolution_range;

static inline int grid_resolution_axis(double extent, double s)
{
    return extent > 0 ? (int)fmin(fmax(round(extent * s), 1), 1 << 20) : 1;
}

static inline double grid_resolution_product(const double extent[3], double s)
{
    return (double)grid_resolution_axis(extent[0], s) * grid_resolution_axis(extent[1], s) *
           grid_resolution_axis(extent[2], s);
}

static inline grid_resolution_range grid_resolution_allowed(const double extent[3], long surfaces, double density,
                                                            long cap)
{
    double volume = 1;
    int spanned = 0;
    for (int a = 0; a < 3; a++)
        if (extent[a] > 0)
            volume *= extent[a], spanned++;
    const double wanted = density * (double)surfaces, cells = fmax(1, fmin(wanted, (double)cap));
    const double s0 = spanned ? pow(cells / volume, 1.0 / spanned) : 0;
    grid_resolution_range r = {.capped = wanted > (double)cap || grid_resolution_product(extent, s0) > (double)cap};
    double fit = s0, over = s0; /* the product at `fit` is within the cap, at `over` above it (once found) */
    if (grid_resolution_product(extent, s0) > (double)cap)
        fit = 0; /* the product is 1 at s = 0 */
    else
        for (int k = 0; k < 1100 && grid_resolution_product(extent, over) <= (double)cap; k++)
            fit = over, over *= 2;
    if (grid_resolution_product(extent, over) > (double)cap) /* bisect down to neighbouring doubles */
        for (double mid = fit + (over - fit) / 2; mid > fit && mid < over; mid = fit + (over - fit) / 2)
            *(grid_resolution_product(extent, mid) <= (double)cap ? &fit : &over) = mid;
    for (int a = 0; a < 3; a++) {
        r.lowest[a] = grid_resolution_axis(extent[a], r.capped ? 0.9 * fmin(s0, fit) * (1 - 1e-9) : s0);
        r.highest[a] = grid_resolution_axis(extent[a], r.capped ? over * (1 + 1e-9) : s0);
    }
    return r;
}

#endif
