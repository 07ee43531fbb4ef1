/* fast_grid.h - chapter 11's lab: the same query as the lesson's grid, made fast.
 *
 * The lesson's grid (11_grid/grid.h) lists each surface in the cells its box
 * overlaps and marches the ray cell by cell.  This grid answers the same
 * query, bit for bit, with more machinery: a triangle is listed only in the
 * cells it touches (a separating-axis test), each entry carries the part of
 * the surface's box inside its cell in bytes (culling, four entries at a
 * time: a cell's list is packed in rows, fast_pack.c), a mailbox skips
 * surfaces already tested along the ray, a ray in an empty cell leaps
 * over the largest cube of empty cells ahead of it in one step (Cohen and
 * Sheffer's proximity clouds, a cube per octant of directions), and a cell
 * that lists many surfaces gets a grid of its own (two levels, Kalojanov,
 * Billeter and Slusallek 2011).  The triangles of a watertight list take the
 * watertight test with its ray part made once per ray, and a box of twelve
 * triangles whose faces share cells is listed and tested as one box
 * (fast_boxes.h).  A scene of a few surfaces is tested as a list, without
 * cells (fast_few.c).
 *
 * fast_grid_intersect returns what the lesson's grid_intersect and chapter
 * 04's surfaces_intersect return: the same surface and bit for bit the same
 * t, the first in the list among equal t.  The lab's README measures what
 * each technique buys.
 */
#ifndef CH11_LAB_FAST_GRID_H
#define CH11_LAB_FAST_GRID_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "04_many_shapes/surface.h"

/* snippet: fast_grid_options */
typedef struct {
    double density;  /* cells per surface: n_x n_y n_z is about density x (number of surfaces) */
    long max_cells;  /* the cap on n_x n_y n_z */
    bool mailbox;    /* skip a surface already tested along the ray */
    bool leap;       /* leap over blocks of empty cells in one step */
    bool cull;       /* test a surface only when the ray passes through its box */
    int split;       /* a cell that lists more surfaces than this gets a grid of its own; 0: one level */
    int prefetch;    /* FAST_GRID_PREFETCH_*: fetch the next cell and the surfaces to test ahead of their use */
    bool normals;    /* keep each triangle's unit normal for the hit's record (24 bytes a surface) */
    bool boxes;      /* test a box's twelve triangles as one box (fast_boxes.h) */
    int list_up_to;  /* a scene whose surfaces cost a ray at most this many triangle tests (a box 1.25, a
                      * sphere 4) is tested as a list, without cells; large surfaces that cost at most
                      * this are tested apart from the cells; 0: cells always, nothing apart */
} fast_grid_options;
/* end snippet */

/* Prefetching: AUTO (0, so the default of a zeroed struct) when the grid and
 * its surfaces take more than FAST_GRID_PREFETCH_FROM bytes (below that they
 * stay in the processor's caches, where the extra work only costs), ON
 * always, OFF never. */
enum { FAST_GRID_PREFETCH_AUTO, FAST_GRID_PREFETCH_ON, FAST_GRID_PREFETCH_OFF };
#define FAST_GRID_PREFETCH_FROM (4L << 20)

#define FAST_GRID_DEFAULT_DENSITY 2.0
#define FAST_GRID_DEFAULT_MAX_CELLS (1L << 24)
#define FAST_GRID_DEFAULT_SPLIT 48
#define FAST_GRID_DEFAULT_LIST_UP_TO 9

/* An entry whose `surface` is FAST_GRID_SUB + s stands for the cell's own
 * grid, subs[s]: the first entry of a cell that has one, followed by the
 * surfaces that span the cell (which its grid leaves out). */
#define FAST_GRID_SUB 0x80000000u

/* In the packed lists (fast_pack.c), an entry FAST_GRID_BOX + b stands for
 * box b of g->boxes (fast_boxes.h), which the build lists by its first
 * triangle: the march tells it from a surface without a load. */
#define FAST_GRID_BOX 0x40000000u

/* A surface's box inside a cell is kept in steps of 1/FAST_GRID_BOX_STEPS of the
 * cell's frame, one byte per side; 127 leaves each byte's top bit free, so
 * that the march compares all six sides at once in one 64-bit word. */
#define FAST_GRID_BOX_STEPS 127

/* snippet: grid */
/* One entry of a cell's list as the build writes it: 12 bytes.  The grid,
 * once built, keeps its lists packed for the march (`lists`). */
typedef struct {
    uint32_t surface; /* index into the surface list */
    uint8_t box[8];   /* the part of the surface's box (widened by the margin) inside the cell,
                       * in 127ths of the cell's frame (the cell widened by the margin),
                       * rounded outwards (lo x, y, z, hi x, y, z, then two zeros); zeros
                       * when culling is off */
} fast_grid_entry;

typedef struct fast_grid fast_grid;
struct fast_boxes;
struct fast_grid {
    const surface_list *list; /* the surfaces; the grid holds their indices only */
    vec3 lo, hi;              /* the grid's box: the surfaces' bounding box, widened by `margin` */
    vec3 cell;                /* the size of one cell along x, y and z */
    vec3 inv_cell;            /* 1 / cell */
    real lo_a[3], hi_a[3];    /* lo and hi again, as arrays the march indexes by axis */
    real cell_a[3];           /* cell, as an array */
    real inv_cell_a[3];       /* inv_cell, as an array */
    real per_unit[3];         /* FAST_GRID_BOX_STEPS / (cell_a + 2 margin): steps of a cell's frame per unit length */
    real frame_step[3];       /* (cell_a + 2 margin) / FAST_GRID_BOX_STEPS: the length of one step of a cell's frame */
    real *plane[3];           /* plane[a][k] = lo_a + k cell_a: the cell boundaries along axis a, for
                               * k = -beyond .. n_a + beyond (a leap's cube may reach beyond the grid) */
    int beyond;               /* the largest side of a leap's cube: 255, or the largest n_a + 1 if less */
    int n[3];                 /* cells along x, y and z */
    long stride[3];           /* what a step of one cell along x, y, z adds to a cell's place: 1, n_x, n_x n_y */
    /* The cells' lists, flat (compressed sparse rows): cell c = i + n_x (j +
     * n_y k) lists n = start[c + 1] - start[c] surfaces, in increasing index,
     * in a block of 3 n words at lists + 3 start[c]: the n surfaces, then
     * their boxes' low sides, then their high sides, a box's three sides in
     * one word (x | y << 8 | z << 16, fast_pack.c). */
    uint32_t *start;          /* n_x n_y n_z + 1 offsets */
    uint32_t *lists;          /* the blocks; NULL while the grid is built */
    fast_grid_entry *refs;    /* while the grid is built: the entries, refs[start[c]] .. refs[start[c + 1] - 1];
                               * NULL after (their memory holds `lists`) */
    uint8_t *empty;           /* per octant o (bit 0: x decreasing, 1: y, 2: z) and cell c,
                               * empty[o n_cells + c]: the cube of cells from c up to that many - 1
                               * cells ahead in octant o holds nothing; 0 for a cell with surfaces.
                               * A table per octant, so that a ray reads one (a cache line holds
                               * 64 cells' worth for it).  NULL when leaping is off */
    uint32_t *unbinned;       /* surfaces without finite bounds: tested for every ray */
    uint32_t *units;          /* a scene of few surfaces (list_up_to): all of them with finite bounds, entries
                               * as the lists have them, tested for every ray; the grid then has no cells.
                               * NULL otherwise */
    long n_units;
    uint32_t *apart;          /* the few large surfaces of a scene (a floor under it; list_up_to), entries as the
                               * lists have them, tested for every ray before the march: the cells cover the
                               * other surfaces only.  NULL when there are none */
    long n_apart;
    vec3 *normal;             /* with fast_grid_options.normals, per surface: a triangle's triangle_normal (the
                               * record of a hit needs it; a division and a square root in a chain); else NULL */
    struct fast_boxes *boxes; /* the boxes of twelve triangles among the surfaces (fast_boxes.h): a cell lists
                               * a box once, by its first triangle, and the march tests it as one; NULL
                               * when there are none, and in a built sub-grid (the march has the top's) */
    fast_grid *subs;          /* the grids of the cells that have their own (two levels), over the
                               * cell's box and the surfaces it lists; they have no subs themselves */
    long n_subs;
    long n_cells, n_refs, n_unbinned;
    real margin;              /* every surface's box is widened by this before it is binned */
    real scale;               /* the largest coordinate of the box, for the rounding bounds */
    bool mailbox;
    bool cull;                /* the boxes are filled in */
    bool prefetch;            /* the march prefetches (the top grid's choice holds for its subs) */
    bool spheres;             /* some surface is a sphere: culled in cells of few entries too (the top grid's) */
    size_t peak_bytes;        /* the most memory the build held at once */
};
/* end snippet */

/* What a march did: added to by fast_grid_intersect_counted. */
typedef struct {
    uint64_t cells;  /* cells visited */
    uint64_t leaps;  /* of those, the cells left by a leap over a cube of empty cells */
    uint64_t tests;  /* surface_intersect calls */
    uint64_t culled; /* surfaces of those cells whose boxes the ray passes by */
} fast_grid_counts;

/* The default knobs: FAST_GRID_DEFAULT_DENSITY, FAST_GRID_DEFAULT_MAX_CELLS, mailboxing, leaping, culling
 * and boxes on, two levels from FAST_GRID_DEFAULT_SPLIT surfaces in a cell, prefetching by size, no normals kept,
 * a list up to FAST_GRID_DEFAULT_LIST_UP_TO triangle tests. */
fast_grid_options fast_grid_default_options(void);

/* Builds the grid of `list`, which must outlive it and not change.  Returns
 * 0, or -1 with the problem in err (out of memory, more cell entries than
 * 32-bit offsets hold, a bad knob). */
int fast_grid_build(fast_grid *g, const surface_list *list, fast_grid_options opt, char *err, size_t err_size);
void fast_grid_free(fast_grid *g);

/* The grid's own memory in bytes (the surfaces aside). */
size_t fast_grid_memory(const fast_grid *g);

/* The cells a box [box_lo, box_hi] overlaps: first[a] .. last[a] along each
 * axis a, clamped to the grid; first[a] > last[a] on some axis when the box
 * lies wholly outside.  A box that touches a cell boundary overlaps the
 * cells on both sides. */
void fast_grid_cell_range(const fast_grid *g, vec3 box_lo, vec3 box_hi, int first[3], int last[3]);

/* The hit with the smallest t in (t_min, t_max), as surfaces_intersect
 * finds it over g->list: the same surface, the same t, the same record. */
bool fast_grid_intersect(const fast_grid *g, ray r, real t_min, real t_max, hit_record *hit);

/* The same, adding what the march did to *counts (when not NULL). */
bool fast_grid_intersect_counted(const fast_grid *g, ray r, real t_min, real t_max, hit_record *hit,
                                 fast_grid_counts *counts);

/* The hit alone, without its record: what a caller that only asks which
 * surface, where along the ray and where on a triangle (beta, gamma) gets,
 * as Embree's rtcIntersect1 returns it.  surface_hit_record makes the rest. */
typedef struct {
    int surface;
    real t, beta, gamma;
} fast_grid_hit;

/* fast_grid_intersect's hit, without the record: the same surface, t, beta and gamma. */
bool fast_grid_closest(const fast_grid *g, ray r, real t_min, real t_max, fast_grid_hit *hit);

#endif
