/* fast_noted.h - chapter 11's lab: what one ray's march keeps besides the search.
 *
 * The mailbox (the surfaces tested along the ray), the boxes tested along it
 * (fast_boxes.h), and the counts the march adds up.
 */
#ifndef CH11_LAB_FAST_NOTED_H
#define CH11_LAB_FAST_NOTED_H

#include "11_grid/lab/fast_boxes.h"
#include "11_grid/lab/fast_cull.h"
#include "11_grid/lab/fast_grid.h"
#include "11_grid/lab/fast_search.h"

/* The mailbox: the last surfaces tested along this ray, one slot per value
 * of (index mod MAILBOX).  A surface found in its slot was tested already
 * and is skipped; a slot taken over by another surface only costs a second
 * test of the first, never a wrong answer.  The boxes tested, the same way
 * by (box mod BOXES_NOTED). */
#define MAILBOX 32
#define BOXES_NOTED 8

typedef struct {
    uint32_t mailbox[MAILBOX];
    uint32_t box_done[BOXES_NOTED];
    const struct fast_boxes *boxes; /* the top grid's, or NULL */
    uint64_t cells, leaps, culled;
    bool prefetch; /* the top grid's */
    bool spheres;  /* the top grid's: robust spheres are culled in cells of few entries too */
} march_state;

/* Before the march of a ray through g, the top grid. */
static inline void noted_start(march_state *ms, const fast_grid *g)
{
    for (int b = 0; b < MAILBOX; b++)
        ms->mailbox[b] = UINT32_MAX;
    if (g->boxes)
        for (int b = 0; b < BOXES_NOTED; b++)
            ms->box_done[b] = FAST_BOX_NONE;
    ms->boxes = g->boxes;
}

/* Whether surface k was tested already along the ray (the mailbox). */
static inline bool tested_already(const march_state *ms, bool use_mailbox, uint32_t k)
{
    return use_mailbox && ms->mailbox[k % MAILBOX] == k;
}

/* Entry k of a cell of grid g against the ray, noted in the mailbox: surface
 * k, or for FAST_GRID_BOX + b, box b, once along the ray (test_box, with the
 * march's p, inv_d and slack of the ray). */
static inline void test_noted(search *s, march_state *ms, const fast_grid *g, const real p[3], const real inv_d[3],
                              const real slack[3], bool use_mailbox, uint32_t k)
{
    if (use_mailbox)
        ms->mailbox[k % MAILBOX] = k;
    const uint32_t b = k - FAST_GRID_BOX;
    if (k < FAST_GRID_BOX) {
        test_surface(s, k);
    } else if (ms->box_done[b % BOXES_NOTED] != b) {
        ms->box_done[b % BOXES_NOTED] = b;
        ms->culled += test_box(s, &ms->boxes->box[b], p, inv_d, slack, g->margin);
    }
}

/* The n entries of a cell of few entries of grid g (cell i; its surfaces,
 * its boxes' low and high sides as the packed lists have them), each tested
 * once along the ray, without sifting.  A sphere's test costs four of a
 * triangle's: where the scene has spheres (ms->spheres), a sphere's box in
 * the cell is looked at first (passes_box, the cell's frame made at its
 * first sphere), as a cell of many entries looks at every box.  Not for the
 * lecture's textbook formula, whose roots for a far or small sphere may lie
 * well outside its box: a list of those takes the loop without the look. */
static inline void test_entries(search *s, march_state *ms, const fast_grid *g, const uint32_t *surface,
                                const uint32_t *lo, const uint32_t *hi, uint32_t n, cull_frame *f, const int i[3],
                                const real p[3], const real d[3], const real inv_d[3], const real slack[3])
{
    const bool use_mailbox = g->mailbox;
    if (!ms->spheres) { /* a loop of its own: no look at the kind of each */
        for (uint32_t j = 0; j < n; j++)
            if (!tested_already(ms, use_mailbox, surface[j]))
                test_noted(s, ms, g, p, inv_d, slack, use_mailbox, surface[j]);
        return;
    }
    bool framed = false;
    for (uint32_t j = 0; j < n; j++) {
        const uint32_t k = surface[j];
        if (tested_already(ms, use_mailbox, k))
            continue;
        if (k < FAST_GRID_BOX && s->list->items[k].kind == SHAPE_SPHERE) {
            if (!framed) {
                if (!f->started)
                    cull_start(f, g, d, inv_d);
                cull_cell(f, g, i, p, inv_d, slack);
                framed = true;
            }
            if (!passes_box(unpack_box(lo[j], hi[j]).side, f, s->t_min, s->upper)) {
                ms->culled++;
                continue;
            }
        }
        test_noted(s, ms, g, p, inv_d, slack, use_mailbox, k);
    }
}

#endif
