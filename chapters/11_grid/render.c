/* render.c - chapter 11's renderer: chapter 10's, with the closest hit through the uniform grid.
 *
 * Knobs: chapter 10's, and --grid-density (cells per surface), --grid-cells
 * (the cap on the cells), --accel=grid|list (list: chapter 04's linear scan,
 * that is chapter 10 as it is).  The lab (lab/README.md) measures the grid
 * and adds a faster one.
 */
#include "05_lambert/renderer/shading_stage.h"
#include "11_grid/renderer/grid_stage.h"
#include "11_grid/scenes/grid_scene.h"

int main(int argc, char **argv)
{
    grid_knobs settings = GRID_KNOBS_DEFAULT;
    knob rows[MAX_STAGE_KNOBS];
    stage_knobs aimed = {0};
    int n_rows = grid_knob_rows(&settings, rows, &aimed);
    /* snippet: stage */
    const shading_stage stage = {
        .name = "11_grid",
        .summary = "11_grid: the closest hit through a uniform grid (3D-DDA), shaded as in chapter 10",
        .knobs = rows,
        .n_knobs = n_rows,
        .modelled = INTERP_MODELLED,
        .shade = shade_interp, /* chapter 10's shading ... */
        .shade_knobs = aimed,
        .build_query = grid_query, /* ... of the hits the grid finds */
        .query_knobs = &settings,
        .builtin = grid_scene,
        .accelerated = true,
    };
    /* end snippet */
    return shading_main(&stage, argc, argv);
}
