/* render.c - chapter 11's renderer: chapter 10's, with the closest hit through the uniform grid.
 *
 * Knobs: chapter 10's, and --grid-density (cells per surface), --grid-cells
 * (the cap on the cells), --accel=grid|list (list: chapter 04's linear scan,
 * that is chapter 10 as it is).  The lab (lab/README.md) measures the grid
 * and adds a faster one.
 */
#include "11_grid/grid_stage.h"

int main(int argc, char **argv)
{
    /* snippet: stage */
    grid_knobs settings = GRID_KNOBS_DEFAULT;
    knob rows[MAX_STAGE_KNOBS];
    const shading_stage stage = grid_stage(&settings, rows); /* interp_stage(...): chapter 10's stage over the grid */
    /* end snippet */
    return shading_main(&stage, argc, argv);
}
