/* fast_boxes.h - chapter 11's lab: a box's twelve triangles tested as one box.
 *
 * The scene reader makes a box of twelve triangles, two in each face
 * (box_triangles).  The build finds such runs in the list (fast_boxes.c):
 * twelve triangles in a row whose vertices are corners of their bounding
 * box, two in the plane of each face.  When the march meets the first of
 * them along a ray, test_box cuts the ray against the box's slabs and gives
 * the triangle test only to the two triangles of each face whose plane the
 * ray crosses inside the box and within the window, the faces it enters by
 * first; no other triangle of the box is tested along that ray.  A face is
 * passed by only where the ray misses the face's own box widened by the
 * grid's margin and the crossings' rounding slack: the rule that every
 * cell's list and every culled box of the grid stand on, so the hits are
 * the linear scan's, bit for bit.
 */
#ifndef CH11_LAB_FAST_BOXES_H
#define CH11_LAB_FAST_BOXES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "11_grid/lab/fast_search.h"

#define FAST_BOX_NONE UINT32_MAX

typedef struct fast_box {
    real lo[3], hi[3];     /* the box: its triangles' vertices are its corners */
    uint32_t first;        /* its twelve triangles are surfaces first .. first + 11 */
    uint32_t face[6][2];   /* the triangles in each face's plane: x low, x high, y low, y high, z low, z high */
} fast_box;

typedef struct fast_boxes {
    uint32_t *of;  /* per surface of the list: the box it is a triangle of, or FAST_BOX_NONE; NULL when n = 0 */
    fast_box *box;
    long n;
    long n_surfaces; /* the list's */
} fast_boxes;

/* The boxes among the surfaces of `list`: *found is NULL when it has none,
 * else allocated.  False when out of memory. */
bool fast_boxes_find(fast_boxes **found, const surface_list *list);
/* Keeps the boxes that some axis a crosses in at most two cells of size
 * cell[a] (a floor, a stick, a box of about a cell): where a box's faces
 * share cells, its triangles are tested there as they come in the lists,
 * faces behind the ray as well; a larger box's triangles stay triangles,
 * listed cell by cell where each one is.  Keeps also the boxes whose
 * triangles `keep` flags (NULL: none), which are tested apart from the cells.
 * Frees *b and sets it to NULL when none is kept. */
void fast_boxes_keep_small(fast_boxes **b, const real cell[3], const bool *keep);
void fast_boxes_free(fast_boxes *b); /* b may be NULL */
size_t fast_boxes_memory(const fast_boxes *b); /* 0 for NULL */

/* The triangles of box b against the ray p + t d, whose 1 / d_a (0 where the
 * ray never crosses a plane of axis a) and crossings' rounding slack_a the
 * march has made, with the grid's margin: only those of the faces the ray
 * can meet within the window (s->t_min, s->upper), as test_surface.  Returns
 * how many it passed by.  A call, not inline: the march's loops stay small
 * where no box is listed. */
uint32_t test_box(search *s, const fast_box *b, const real p[3], const real inv_d[3], const real slack[3], real margin);

#endif
