/* grid_stage.h - chapter 11: the grid as the closest-hit query of chapter 10's stage.
 *
 * Chapter 11 shades exactly as chapter 10 does and changes one question,
 * "what does this ray hit first?": grid_intersect in place of chapter 04's
 * linear scan, for eye, shadow, reflected and refracted rays alike.  Since
 * the grid returns the linear scan's hit bit for bit, the images are
 * chapter 10's byte for byte, only sooner.
 */
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
 * linear scan under --accel=list; for a stage that shades without chapter
 * 10's faces (the scenes suite renders chapter 07 through it). */
int grid_query(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size);

/* A build_query_fn: chapter 10's face_query around the grid of `list`
 * (grid_settings), or around the linear scan under --accel=list. */
int grid_faces(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size);

/* Chapter 11's stage: chapter 10's over grid_faces, with this chapter's
 * name, knobs and built-in scene. */
shading_stage grid_stage(void);

#endif
