/* fast_cull.c - chapter 11's lab: the clamps of culling's span (fast_cull.h, cull_span).
 *
 * cull_span clamps the ray's span in a cell to the steps 0 .. FAST_GRID_BOX_STEPS with
 * selects, not branches: whether a side is clamped changes from cell to cell, and valgrind's
 * model of the branch predictor counted 1.2 mispredicted branches a ray there on bench-grid's
 * bunny.  With the bounds as constants in the march's own file, gcc folds the truncation of a
 * clamped value into its result and turns each select into a branch to it; defined here, their
 * values are not known there, and the selects stay selects (maxsd and minsd on x86-64):
 * bench-grid's random rays 5 to 7 % more a second, its primary rays 2 to 3 % (speed8.md).
 */
#include "11_grid/lab/fast_cull.h"

const real fast_cull_span_clamp[3] = {(real)-0.5, FAST_GRID_BOX_STEPS + (real)0.5, FAST_GRID_BOX_STEPS - (real)0.5};
