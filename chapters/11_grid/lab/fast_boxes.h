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
 * listed cell by cell where each one is.  Frees *b and sets it to NULL when
 * none is kept. */
void fast_boxes_keep_small(fast_boxes **b, const real cell[3]);
void fast_boxes_free(fast_boxes *b); /* b may be NULL */
size_t fast_boxes_memory(const fast_boxes *b); /* 0 for NULL */

/* snippet: test_box */
/* The face of axis a that the ray crosses at t = at, within +- width: its
 * two triangles, when that crossing can lie in [t_in, t_out] and before the
 * best hit so far.  Returns how many it tested. */
static inline uint32_t test_face(search *s, const uint32_t face[2], real at, real width, real t_in, real t_out)
{
    const real end = t_out < s->upper ? t_out : s->upper;
    if (at - width > end || at + width < t_in)
        return 0;
    test_surface(s, face[0]);
    test_surface(s, face[1]);
    return 2;
}

/* The triangles of box b against the ray p + t d, whose 1 / d_a (0 where the
 * ray never crosses a plane of axis a) and crossings' rounding slack_a the
 * march has made: only those of the faces the ray can meet within the window
 * (s->t_min, s->upper), as test_surface.  Returns how many it passed by. */
static inline uint32_t test_box(search *s, const fast_box *b, const real p[3], const real inv_d[3],
                                const real slack[3], real margin)
{
    /* The slabs: t where the ray crosses the plane of the face it enters by
     * along each axis and of the face it leaves by, each within +- width (the
     * margin, and the rounding); [t_in, t_out], where it is inside all three. */
    real t_in = s->t_min, t_out = s->upper, enters[3], leaves[3], width[3];
    int near[3]; /* the face it enters by along a: 2 a (low) or 2 a + 1 (high) */
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        near[a] = 2 * a + (inv_d[a] < 0);
        if (inv_d[a] == 0) { /* inside the slab along a for every t, or beside the box */
            if (p[a] < b->lo[a] - margin || p[a] > b->hi[a] + margin)
                return 12;
            enters[a] = leaves[a] = 0;
            width[a] = REAL_INFINITY; /* both faces of a stay in: the ray never leaves their planes' slab */
            continue;
        }
        const real at_lo = (b->lo[a] - p[a]) * inv_d[a], at_hi = (b->hi[a] - p[a]) * inv_d[a];
        enters[a] = inv_d[a] < 0 ? at_hi : at_lo;
        leaves[a] = inv_d[a] < 0 ? at_lo : at_hi;
        width[a] = margin * real_abs(inv_d[a]) + slack[a];
        const real in = enters[a] - width[a], out = leaves[a] + width[a];
        t_in = in > t_in ? in : t_in; /* a NaN is passed over: it never culls */
        t_out = out < t_out ? out : t_out;
    }
    if (t_in > t_out)
        return 12;
    /* The faces it enters by first: a hit there closes the window on those it leaves by. */
    uint32_t tested = 0;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++)
        tested += test_face(s, b->face[near[a]], enters[a], width[a], t_in, t_out);
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++)
        tested += test_face(s, b->face[near[a] ^ 1], leaves[a], width[a], t_in, t_out);
    return 12 - tested;
}
/* end snippet */

#endif
