/* grid_stage.h - chapter 11: the grid as the closest-hit query of chapter 10's stage (README,
 * "What the renderer shows"): chapter 10's images byte for byte, only sooner. */
#ifndef CH11_RENDERER_GRID_STAGE_H
#define CH11_RENDERER_GRID_STAGE_H

#include <stddef.h>

#include "05_lambert/renderer/shading_stage.h"
#include "10_interpolation/renderer/options.h"
#include "11_grid/grid.h"

/* The knobs of chapter 11: chapter 10's, then the grid's. */
typedef struct {
    interp_knobs interp; /* chapters 06-10 */
    real density;        /* --grid-density: cells per surface */
    int max_cells;       /* --grid-cells: the cap on the cells */
    int accel;           /* --accel: GRID_ACCEL_GRID, or chapter 04's linear scan (chapter 10 as it is) */
} grid_knobs;
enum { GRID_ACCEL_GRID, GRID_ACCEL_LIST };
#define GRID_KNOBS_DEFAULT \
    {.interp = INTERP_KNOBS_DEFAULT, .density = (real)GRID_DEFAULT_DENSITY, .max_cells = (int)GRID_DEFAULT_MAX_CELLS}

/* The option rows of chapters 06-11's knobs, and the tracer's knobs, aimed at *k; returns how many rows. */
int grid_knob_rows(grid_knobs *k, knob *rows, stage_knobs *aimed);

/* A build_query_fn on a grid_knobs: the grid of `list` (--accel=list: chapter 04's linear scan);
 * 0, or -1 with "path: problem". */
int grid_query(const void *knobs, const surface_list *list, const scene *desc, hit_query *q, char *err,
               size_t err_size);

#endif
