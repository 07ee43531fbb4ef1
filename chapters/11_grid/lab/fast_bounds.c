/* fast_bounds.c - chapter 11's lab: the bounds of what a cell lists: a surface, or a box of twelve triangles. */
#include "11_grid/lab/fast_build.h"

#include "11_grid/lab/fast_boxes.h"
#include "box.h"

/* A surface's bounding box: a sphere's centre +- R, a triangle's vertices' extremes. */
void fast_grid_surface_bounds(const surface *s, vec3 *lo, vec3 *hi)
{
    if (s->kind == SHAPE_SPHERE) {
        real r = real_abs(s->sphere.radius);
        vec3 c = s->sphere.center;
        *lo = vec3_make(c.x - r, c.y - r, c.z - r);
        *hi = vec3_make(c.x + r, c.y + r, c.z + r);
    } else {
        const triangle *t = &s->triangle;
        *lo = vec3_make(lesser(t->a.x, lesser(t->b.x, t->c.x)), lesser(t->a.y, lesser(t->b.y, t->c.y)),
                        lesser(t->a.z, lesser(t->b.z, t->c.z)));
        *hi = vec3_make(greater(t->a.x, greater(t->b.x, t->c.x)), greater(t->a.y, greater(t->b.y, t->c.y)),
                        greater(t->a.z, greater(t->b.z, t->c.z)));
    }
}

/* The bounds of what entry k of a cell stands for: surface k, or the box of
 * which k is the first triangle (a box is listed by its first triangle). */
void fast_grid_entry_bounds(const fast_grid *g, uint32_t k, vec3 *lo, vec3 *hi)
{
    const uint32_t b = g->boxes ? g->boxes->of[k] : FAST_BOX_NONE;
    if (b == FAST_BOX_NONE) {
        fast_grid_surface_bounds(&g->list->items[k], lo, hi);
        return;
    }
    const fast_box *box = &g->boxes->box[b];
    *lo = vec3_make(box->lo[0], box->lo[1], box->lo[2]);
    *hi = vec3_make(box->hi[0], box->hi[1], box->hi[2]);
}

/* The culling box of box b's entry in cell (i, j, k): the parts inside the
 * cell of its triangles' boxes that reach into the cell's frame (a thin box
 * where a face crosses the cell, as its triangles' own are), joined. */
void fast_grid_box_cull_box(const fast_grid *g, const fast_box *b, int i, int j, int k, uint8_t box[6])
{
    const int index[3] = {i, j, k};
    box[0] = box[1] = box[2] = FAST_GRID_BOX_STEPS;
    box[3] = box[4] = box[5] = 0;
    for (uint32_t t = b->first; t < b->first + 12; t++) {
        vec3 lo, hi;
        fast_grid_surface_bounds(&g->list->items[t], &lo, &hi);
        bool reaches = true;
        for (int a = 0; a < 3; a++) {
            const real frame_lo = g->plane[a][index[a]] - g->margin, frame_hi = g->plane[a][index[a] + 1] + g->margin;
            reaches = reaches && vec3_axis(lo, a) - g->margin <= frame_hi && vec3_axis(hi, a) + g->margin >= frame_lo;
        }
        if (!reaches)
            continue;
        uint8_t part[6];
        fast_grid_cull_box(g, lo, hi, i, j, k, part);
        for (int a = 0; a < 3; a++) {
            box[a] = part[a] < box[a] ? part[a] : box[a];
            box[3 + a] = part[3 + a] > box[3 + a] ? part[3 + a] : box[3 + a];
        }
    }
}
