/* fast_query.h - chapter 11's lab: the fast grid as the stage's closest-hit query, counted.
 *
 * The lab's renderer runs chapter 11's stage with --accel=list|grid|fast:
 * the linear scan, the lesson's grid or the fast grid.  Every query adds what it did to the calling
 * thread's tally, which the renderer reads per sample (heat maps) and sums
 * (the report).
 */
#ifndef CH11_LAB_FAST_QUERY_H
#define CH11_LAB_FAST_QUERY_H

#include <stdint.h>

#include "11_grid/renderer/grid_stage.h"
#include "11_grid/lab/fast_grid.h"

/* The lab's knobs: the lesson's (its --accel aside), then the fast grid's. */
typedef struct {
    grid_knobs grid; /* chapters 06-11: the shading's, --grid-density, --grid-cells */
    int accel;   /* LAB_ACCEL_* */
    int mailbox; /* --mailbox, --leap, --cull: 0 on, 1 off (the index of on|off) */
    int leap;
    int cull;
    int split;   /* --split: a cell listing more surfaces than this gets a grid of its own (0: one level) */
    int prefetch; /* --prefetch: auto|on|off, FAST_GRID_PREFETCH_* */
    int boxes;    /* --boxes: 0 on, 1 off */
    int list_up_to; /* --list-up-to: a scene that costs a ray at most this many triangle tests is a list */
} fast_knobs;
enum { LAB_ACCEL_FAST, LAB_ACCEL_GRID, LAB_ACCEL_LIST };
#define FAST_KNOBS_DEFAULT                                                                                             \
    {.grid = GRID_KNOBS_DEFAULT, .accel = LAB_ACCEL_FAST, .split = FAST_GRID_DEFAULT_SPLIT,                            \
     .list_up_to = FAST_GRID_DEFAULT_LIST_UP_TO}

/* What the closest-hit queries of one thread did since the last reset. */
typedef struct {
    uint64_t queries;        /* one per ray of any kind */
    fast_grid_counts counts; /* all of them together */
    fast_grid_counts first;  /* the first query since the reset (a sample's eye ray) */
} query_tally;
extern _Thread_local query_tally query_tally_here;

/* The query under the knobs' accel, built over `list`. */
typedef struct {
    int accel;
    const surface_list *list;
    grid lesson;      /* LAB_ACCEL_GRID */
    fast_grid fast;   /* LAB_ACCEL_FAST */
    double build_seconds;
} lab_query;

/* A build_query_fn whose knobs are a fast_knobs: a lab_query of their accel over `list`. */
int lab_query_build(const void *knobs, const surface_list *list, const scene *desc, hit_query *q, char *err,
                    size_t err_size);

#endif
