/* grid_stage.h - chapter 11: the grid as the closest-hit query of chapter 10's stage (README,
 * "What the renderer shows"): chapter 10's images byte for byte, only sooner. */
#ifndef CH11_GRID_STAGE_H
#define CH11_GRID_STAGE_H

#include <stddef.h>

#include "05_lambert/shading_stage.h"
#include "11_grid/grid.h"

/* The knobs' values (the defaults until the command line changes them). */
typedef struct {
    real density;  /* --grid-density: cells per surface */
    int max_cells; /* --grid-cells: the cap on the cells */
    int accel;     /* --accel: GRID_ACCEL_GRID, or chapter 04's linear scan (chapter 10 as it is) */
} grid_knobs;
enum { GRID_ACCEL_GRID, GRID_ACCEL_LIST };

extern grid_knobs grid_settings;

/* The rows of --grid-density and --grid-cells, for a renderer that lists them. */
enum { GRID_KNOBS = 2 };
extern const knob grid_knob_rows[GRID_KNOBS];

/* A build_query_fn: the grid of `list` (grid_settings), or chapter 04's
 * linear scan under --accel=list.  Returns 0, or -1 with "path: problem". */
int grid_query(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size);

/* Chapter 11's stage: chapter 10's over grid_query, with this chapter's
 * name, knobs and built-in scene. */
shading_stage grid_stage(void);

#endif
