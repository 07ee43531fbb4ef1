/* grid_stage.h - chapter 11: the grid as the closest-hit query of chapter 10's stage.
 *
 * Chapter 11 shades exactly as chapter 10 does and changes one thing, the
 * question "what does this ray hit first?": grid_intersect over the grid in
 * place of chapter 04's linear scan over the list.  In the stage that is
 * one assignment, the build_query_fn:
 *
 *     shading_stage stage = interp_stage(grid_faces);
 *
 * and every chapter's shading code runs unchanged over the grid, for eye,
 * shadow, reflected and refracted rays alike.  grid_intersect returns the
 * hit the linear scan returns (the same surface, bit for bit the same t, the
 * first in the list among equal t), so the images are chapter 10's byte for
 * byte, only sooner.
 */
#ifndef CH11_GRID_STAGE_H
#define CH11_GRID_STAGE_H

#include <stddef.h>
#include <stdint.h>

#include "05_lambert/shading_stage.h"
#include "11_grid/grid.h"

/* The grid's knobs, as the command line sets them (the targets of chapter
 * 11's knobs; the defaults until then). */
typedef struct {
    real density;  /* --grid-density: cells per surface */
    int max_cells; /* --grid-cells: the cap on the cells */
    int mailbox;   /* --mailbox, --leap, --cull: 0 on, 1 off (the index of on|off) */
    int leap;
    int cull;
    int accel;     /* --accel: 0 the grid, 1 chapter 04's linear scan (chapter 10 as it is) */
} grid_knobs;

extern grid_knobs grid_settings;

/* What the closest-hit queries of one thread did: added to by every query,
 * read and reset by whoever counts (the renderer, per sample: the first
 * query after the reset is then the sample's eye ray). */
typedef struct {
    uint64_t queries;   /* closest-hit queries: one per ray of any kind */
    grid_counts counts; /* what they did, all together */
    grid_counts first;  /* what the first query since the reset did */
} grid_tally;

extern _Thread_local grid_tally grid_tally_here;

/* The query the stage runs over: the grid of the view's surface list and
 * what building it took. */
typedef struct {
    grid grid;
    double build_seconds; /* wall-clock time of grid_build */
} grid_query;

/* A build_query_fn: the grid over `list` with grid_settings (accel = grid),
 * or chapter 04's linear scan (accel = the list), both counted in
 * grid_tally_here.  Returns 0, or -1 with "path: problem" in err. */
int grid_query_build(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size);

/* Chapter 10's face_query around grid_query_build: a build_query_fn. */
int grid_faces(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size);

/* Chapter 11's stage: chapter 10's over grid_faces, with this chapter's
 * name and built-in scene. */
shading_stage grid_stage(void);

#endif
