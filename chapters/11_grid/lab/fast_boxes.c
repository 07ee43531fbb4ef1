/* fast_boxes.c - chapter 11's lab: the boxes among a list's triangles, found at build time. */
#include "11_grid/lab/fast_boxes.h"

#include <math.h>
#include <stdlib.h>

/* The axis along which the triangle is flat (its three vertices' coordinates
 * equal), or -1 when there is none or more than one (a degenerate triangle). */
static int flat_axis(const triangle *t)
{
    const real v[3][3] = {{t->a.x, t->a.y, t->a.z}, {t->b.x, t->b.y, t->b.z}, {t->c.x, t->c.y, t->c.z}};
    int axis = -1;
    for (int a = 0; a < 3; a++)
        if (v[0][a] == v[1][a] && v[1][a] == v[2][a]) {
            if (axis >= 0)
                return -1;
            axis = a;
        }
    return axis;
}

static bool flat_triangle(const surface *s) { return s->kind == SHAPE_TRIANGLE && flat_axis(&s->triangle) >= 0; }

/* Whether surfaces first .. first + 11, each a triangle flat along one axis,
 * are a box's: every vertex a corner of their bounding box, which has extent
 * along every axis, and two triangles in the plane of each face.  Fills in *b. */
static bool box_at(const surface_list *list, int first, fast_box *b)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = REAL_INFINITY;
        b->hi[a] = -REAL_INFINITY;
    }
    for (int k = first; k < first + 12; k++) {
        const triangle *t = &list->items[k].triangle;
        const vec3 v[3] = {t->a, t->b, t->c};
        for (int q = 0; q < 3; q++) {
            const real x[3] = {v[q].x, v[q].y, v[q].z};
            for (int a = 0; a < 3; a++) {
                b->lo[a] = x[a] < b->lo[a] ? x[a] : b->lo[a];
                b->hi[a] = x[a] > b->hi[a] ? x[a] : b->hi[a];
            }
        }
    }
    for (int a = 0; a < 3; a++)
        if (!(b->lo[a] < b->hi[a]) || !isfinite(b->lo[a]) || !isfinite(b->hi[a]))
            return false;
    int filled[6] = {0};
    for (int k = first; k < first + 12; k++) {
        const triangle *t = &list->items[k].triangle;
        const vec3 v[3] = {t->a, t->b, t->c};
        for (int q = 0; q < 3; q++) {
            const real x[3] = {v[q].x, v[q].y, v[q].z};
            for (int a = 0; a < 3; a++)
                if (x[a] != b->lo[a] && x[a] != b->hi[a])
                    return false; /* not a corner */
        }
        const int a = flat_axis(t);
        const int face = 2 * a + ((a == 0 ? t->a.x : a == 1 ? t->a.y : t->a.z) == b->hi[a]);
        if (filled[face] == 2)
            return false;
        b->face[face][filled[face]++] = (uint32_t)k;
    }
    b->first = (uint32_t)first;
    return true; /* twelve triangles, at most two a face: two in each */
}

bool fast_boxes_find(fast_boxes **found, const surface_list *list)
{
    *found = NULL;
    fast_boxes *b = NULL;
    long size = 0;
    for (int k = 0; k + 12 <= list->n;) {
        /* a run with a triangle that is not flat along an axis is no box: start past it */
        int flat = 0;
        while (flat < 12 && flat_triangle(&list->items[k + flat]))
            flat++;
        fast_box box;
        if (flat < 12 || !box_at(list, k, &box)) {
            k += flat < 12 ? flat + 1 : 1;
            continue;
        }
        if (!b) {
            b = calloc(1, sizeof *b);
            if (!b || !(b->of = malloc((size_t)list->n * sizeof *b->of))) {
                free(b);
                return false;
            }
            b->n_surfaces = list->n;
            for (int q = 0; q < list->n; q++)
                b->of[q] = FAST_BOX_NONE;
        }
        if (b->n == size) {
            size = size ? 2 * size : 16;
            fast_box *grown = realloc(b->box, (size_t)size * sizeof *grown);
            if (!grown) {
                fast_boxes_free(b);
                return false;
            }
            b->box = grown;
        }
        for (int q = k; q < k + 12; q++)
            b->of[q] = (uint32_t)b->n;
        b->box[b->n++] = box;
        k += 12;
    }
    *found = b;
    return true;
}

void fast_boxes_keep_small(fast_boxes **found, const real cell[3], const bool *keep)
{
    fast_boxes *b = *found;
    long kept = 0;
    for (long k = 0; b && k < b->n; k++) {
        const fast_box *box = &b->box[k];
        bool small = keep && keep[box->first];
        for (int a = 0; a < 3; a++)
            small = small || box->hi[a] - box->lo[a] <= 2 * cell[a];
        for (uint32_t t = box->first; t < box->first + 12; t++)
            b->of[t] = small ? (uint32_t)kept : FAST_BOX_NONE;
        if (small)
            b->box[kept++] = *box;
    }
    if (b && kept == 0) {
        fast_boxes_free(b);
        *found = NULL;
    } else if (b) {
        b->n = kept;
    }
}

void fast_boxes_free(fast_boxes *b)
{
    if (!b)
        return;
    free(b->of);
    free(b->box);
    free(b);
}

size_t fast_boxes_memory(const fast_boxes *b)
{
    return b ? sizeof *b + (size_t)b->n * sizeof *b->box + (size_t)b->n_surfaces * sizeof *b->of : 0;
}

/* snippet: test_box */
/* The face of axis a that the ray crosses at t = at, within +- width: its
 * two triangles, when that crossing can lie in [t_in, t_out] and before the
 * best hit so far.  Returns how many it tested. */
static uint32_t test_face(search *s, const uint32_t face[2], real at, real width, real t_in, real t_out)
{
    const real end = t_out < s->upper ? t_out : s->upper;
    if (at - width > end || at + width < t_in)
        return 0;
    test_surface(s, face[0]);
    test_surface(s, face[1]);
    return 2;
}

uint32_t test_box(search *s, const fast_box *b, const real p[3], const real inv_d[3], const real slack[3], real margin)
{
    /* The slabs: t where the ray crosses the plane of the face it enters by
     * along each axis and of the face it leaves by, each within +- width (the
     * margin, and the rounding); [t_in, t_out], where it is inside all three. */
    real t_in = s->t_min, t_out = s->upper, enters[3], leaves[3], width[3];
    int near[3]; /* the face it enters by along a: 2 a (low) or 2 a + 1 (high) */
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        near[a] = 2 * a + (inv_d[a] < 0);
        if (inv_d[a] == 0) { /* inside the slab along a for every t, or beside the box; */
            const real d_a = a == 0 ? s->r.d.x : a == 1 ? s->r.d.y : s->r.d.z;
            /* a d_a so small that 1 / d_a overflows moves the ray along a only at an enormous t: no cut there */
            if (d_a == 0 && (p[a] < b->lo[a] - margin || p[a] > b->hi[a] + margin))
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
