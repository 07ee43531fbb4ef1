/* fast_build.c - chapter 11's lab: the fast grid's cells, with culling boxes and empty-cube distances. */
#include "11_grid/lab/fast_grid.h"

#include "11_grid/lab/fast_boxes.h"
#include "11_grid/lab/fast_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "11_grid/grid.h"

fast_grid_options fast_grid_default_options(void)
{
    return (fast_grid_options){.density = FAST_GRID_DEFAULT_DENSITY,
                          .max_cells = FAST_GRID_DEFAULT_MAX_CELLS,
                          .mailbox = true,
                          .leap = true,
                          .cull = true,
                          .split = FAST_GRID_DEFAULT_SPLIT,
                          .prefetch = FAST_GRID_PREFETCH_AUTO,
                          .normals = false,
                          .boxes = true,
                          .list_up_to = FAST_GRID_DEFAULT_LIST_UP_TO};
}

static real get(vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

static vec3 widen(vec3 v, real m) { return vec3_make(v.x + m, v.y + m, v.z + m); }

/* The cells a box overlaps: the lesson's grid_cell_range (its exercise), the
 * same arithmetic and the same answers, with its ceil, floor and clamps
 * written out in comparisons: the build runs it for every surface, and the
 * library's calls took a tenth of the sphere's build.  f is where the box
 * starts (ends) in cells from the low corner; for 0 < f <= n, ceil(f) - 1 is
 * the first cell, and for -1 <= f < n - 1, floor(f) the last (a NaN: none). */
void fast_grid_cell_range(const fast_grid *g, vec3 box_lo, vec3 box_hi, int first[3], int last[3])
{
    for (int a = 0; a < 3; a++) {
        const real f_lo = (get(box_lo, a) - get(g->lo, a)) / get(g->cell, a);
        const real f_hi = (get(box_hi, a) - get(g->lo, a)) / get(g->cell, a), n = (real)g->n[a];
        const int t_lo = f_lo > 0 && f_lo <= n ? (int)f_lo : 0, t_hi = f_hi >= -1 && f_hi < n - 1 ? (int)f_hi : 0;
        first[a] = !(f_lo > 0) ? 0 : f_lo > n ? g->n[a] : t_lo + ((real)t_lo < f_lo) - 1;
        last[a] = !(f_hi >= -1) ? -1 : f_hi >= n - 1 ? g->n[a] - 1 : t_hi - (f_hi < (real)t_hi);
    }
}

/* Whether the projections of a triangle (p0, p1, p2: its vertices' dot
 * products with an axis) and of a box (radius r about 0) on that axis are
 * apart.  A NaN never separates. */
static inline bool apart(real p0, real p1, real p2, real r)
{
    real lo = p0 < p1 ? (p0 < p2 ? p0 : p2) : (p1 < p2 ? p1 : p2);
    real hi = p0 > p1 ? (p0 > p2 ? p0 : p2) : (p1 > p2 ? p1 : p2);
    return lo > r || hi < -r;
}

/* Whether a triangle can touch cell (i, j, k), by the separating axis test
 * of Akenine-Moller (2001): the triangle and the box are apart when their
 * projections on some axis are, and it suffices to try the box's three
 * axes (the cell range has done that), the triangle's normal and the nine
 * cross products of a box axis with a triangle edge.  The box is the cell
 * widened by the margin, and each comparison allows a rounding term on top,
 * so the test says yes too often, never too rarely: a triangle is listed in
 * every cell it meets.  Spheres and triangles within one cell's box along
 * every axis are binned by their boxes alone.  The cross product of the x
 * axis and an edge e is (0, -e_z, e_y), and so for y and z: its projections
 * are written with the two terms that are not zero (the third would add an
 * exact zero: the data are finite here, or the surface is not binned). */
static bool triangle_touches_cell(const fast_grid *g, const triangle *tri, int i, int j, int k)
{
    vec3 h = widen(vec3_scale(g->cell, (real)0.5), g->margin);
    vec3 m = vec3_make(g->lo.x + ((real)i + (real)0.5) * g->cell.x, g->lo.y + ((real)j + (real)0.5) * g->cell.y,
                       g->lo.z + ((real)k + (real)0.5) * g->cell.z);
    /* the vertices relative to the cell's centre, and the edges */
    const vec3 v[3] = {vec3_sub(tri->a, m), vec3_sub(tri->b, m), vec3_sub(tri->c, m)};
    const vec3 e[3] = {vec3_sub(v[1], v[0]), vec3_sub(v[2], v[1]), vec3_sub(v[0], v[2])};
    const real rounding = 8 * REAL_EPSILON * (g->scale + vec3_max_abs(m));
    const vec3 n = vec3_cross(e[0], e[1]); /* the normal */
    real r = real_abs(n.x) * h.x + real_abs(n.y) * h.y + real_abs(n.z) * h.z +
             rounding * (real_abs(n.x) + real_abs(n.y) + real_abs(n.z));
    if (apart(vec3_dot(v[0], n), vec3_dot(v[1], n), vec3_dot(v[2], n), r))
        return false;
    for (int b = 0; b < 3; b++) {
        const real ex = e[b].x, ey = e[b].y, ez = e[b].z, ax = real_abs(ex), ay = real_abs(ey), az = real_abs(ez);
        /* x cross e = (0, -e_z, e_y) */
        r = (az * h.y + ay * h.z) + rounding * (az + ay);
        if (apart(v[0].y * -ez + v[0].z * ey, v[1].y * -ez + v[1].z * ey, v[2].y * -ez + v[2].z * ey, r))
            return false;
        /* y cross e = (e_z, 0, -e_x) */
        r = (az * h.x + ax * h.z) + rounding * (az + ax);
        if (apart(v[0].x * ez + v[0].z * -ex, v[1].x * ez + v[1].z * -ex, v[2].x * ez + v[2].z * -ex, r))
            return false;
        /* z cross e = (-e_y, e_x, 0) */
        r = (ay * h.x + ax * h.y) + rounding * (ay + ax);
        if (apart(v[0].x * -ey + v[0].y * ex, v[1].x * -ey + v[1].y * ex, v[2].x * -ey + v[2].y * ex, r))
            return false;
    }
    return true;
}

/* snippet: cull_box */
/* The part of a surface's box [lo, hi] (widened by the margin) inside cell
 * (i, j, k), for culling: along each axis, in FAST_GRID_BOX_STEPS-ths of the cell's frame,
 * the cell widened by the margin on both sides, rounded outwards (floor for
 * the low side, ceil for the high side, each a hundredth of a step further
 * for the rounding of this arithmetic) and clamped to the frame.  One byte
 * per side: 6 bytes per entry, read in order with the entries, where a
 * float box per surface took 24 bytes read from anywhere. */
static void cull_box(const fast_grid *g, vec3 lo, vec3 hi, int i, int j, int k, uint8_t box[6])
{
    const int index[3] = {i, j, k};
    for (int a = 0; a < 3; a++) {
        double steps = FAST_GRID_BOX_STEPS / ((double)get(g->cell, a) + 2 * (double)g->margin); /* per unit */
        double origin = (double)get(g->lo, a) + index[a] * (double)get(g->cell, a) - (double)g->margin;
        double f_lo = ((double)get(lo, a) - g->margin - origin) * steps - 0.01;
        double f_hi = ((double)get(hi, a) + g->margin - origin) * steps + 0.01;
        const int top = FAST_GRID_BOX_STEPS, t_hi = f_hi > 0 && f_hi < top ? (int)f_hi : 0; /* truncated: floor, ceil */
        box[a] = (uint8_t)(f_lo <= 0 ? 0 : f_lo >= top ? top : (int)f_lo);
        box[3 + a] = (uint8_t)(f_hi <= 0 ? 0 : f_hi >= top ? top : t_hi + (t_hi < f_hi));
    }
}
/* end snippet */

void fast_grid_cull_box(const fast_grid *g, vec3 lo, vec3 hi, int i, int j, int k, uint8_t box[6])
{
    cull_box(g, lo, hi, i, j, k, box);
}

/* The cells each surface is listed in, found once (the separating axis test
 * is the build's dearest step) and kept until the entries are written. */
typedef struct {
    uint32_t cell, surface;
} binned;

typedef struct {
    binned *at;
    size_t n, size;
} bin_list;

/* Counts surface s in every cell it overlaps and adds (cell, index) to bins:
 * index is s's own, or for the triangles of a box its first one's, each cell
 * once (stamp: per cell, the last box listed there, which is `box`; NULL for
 * a surface alone).  False when out of memory. */
static bool bin_surface(fast_grid *g, const surface *s, uint32_t index, uint32_t *count, bin_list *bins,
                        uint32_t *stamp, uint32_t box)
{
    vec3 lo, hi;
    fast_grid_surface_bounds(s, &lo, &hi);
    if (!vec3_is_finite(lo) || !vec3_is_finite(hi))
        return true; /* unbinned: tested for every ray */
    int first[3], last[3];
    fast_grid_cell_range(g, widen(lo, -g->margin), widen(hi, g->margin), first, last);
    /* A triangle whose box lies inside the grid and in one slab of cells
     * along two axes meets every cell of its range (in the middle ones, the
     * plane between; in the end ones, its extreme vertex): only a box that
     * spans two axes, or reaches beyond a cell's own grid, needs the
     * separating axis test. */
    int spanned = (first[0] < last[0]) + (first[1] < last[1]) + (first[2] < last[2]);
    bool inside = lo.x - g->margin >= g->lo.x && lo.y - g->margin >= g->lo.y && lo.z - g->margin >= g->lo.z &&
                  hi.x + g->margin <= g->hi.x && hi.y + g->margin <= g->hi.y && hi.z + g->margin <= g->hi.z;
    bool by_axes = s->kind == SHAPE_TRIANGLE && (spanned >= 2 || (spanned == 1 && !inside));
    for (int k = first[2]; k <= last[2]; k++)
        for (int j = first[1]; j <= last[1]; j++)
            for (int i = first[0]; i <= last[0]; i++) {
                if (by_axes && !triangle_touches_cell(g, &s->triangle, i, j, k))
                    continue;
                long c = i + (long)g->n[0] * (j + (long)g->n[1] * k);
                if (stamp && stamp[c] == box)
                    continue; /* the box is listed there already */
                if (stamp)
                    stamp[c] = box;
                if (bins->n == bins->size) {
                    size_t size = bins->size ? 2 * bins->size : 1024;
                    binned *at = realloc(bins->at, size * sizeof *at);
                    if (!at)
                        return false;
                    bins->at = at;
                    bins->size = size;
                }
                bins->at[bins->n++] = (binned){(uint32_t)c, index};
                count[c]++;
            }
    return true;
}

/* Writes the entries that bins lists, each at fill[cell]++, with the part of
 * its surface's box inside the cell when culling is on. */
static void write_entries(fast_grid *g, const bin_list *bins, uint32_t *fill)
{
    vec3 lo = {0, 0, 0}, hi = {0, 0, 0};
    uint32_t boxed = UINT32_MAX; /* the surface whose box lo, hi is */
    const uint32_t n0 = (uint32_t)g->n[0], n1 = (uint32_t)g->n[1];
    for (size_t e = 0; e < bins->n; e++) {
        const binned b = bins->at[e];
        fast_grid_entry *entry = &g->refs[fill[b.cell]++];
        *entry = (fast_grid_entry){.surface = b.surface};
        if (!g->cull)
            continue;
        const uint32_t in_box = g->boxes ? g->boxes->of[b.surface] : FAST_BOX_NONE;
        if (in_box != FAST_BOX_NONE) {
            fast_grid_box_cull_box(g, &g->boxes->box[in_box], (int)(b.cell % n0), (int)(b.cell / n0 % n1),
                                   (int)(b.cell / n0 / n1), entry->box);
            continue;
        }
        if (b.surface != boxed) {
            /* a surface alone: a box took the branch above */
            fast_grid_surface_bounds(&g->list->items[b.surface], &lo, &hi);
            boxed = b.surface;
        }
        cull_box(g, lo, hi, (int)(b.cell % n0), (int)(b.cell / n0 % n1), (int)(b.cell / n0 / n1), entry->box);
    }
}

/* The entries of the table of cell boundaries: n_a + 1 planes per axis and
 * g->beyond more on either side (the largest cube a leap takes). */
static size_t plane_count(const fast_grid *g)
{
    return (size_t)g->n[0] + g->n[1] + g->n[2] + 3 * (1 + 2 * (size_t)g->beyond);
}

int fast_grid_fill(fast_grid *g, const uint32_t *subset, long n, bool leap, char *err, size_t err_size)
{
    vec3 size = vec3_sub(g->hi, g->lo);
    g->cell = vec3_make(size.x / (real)g->n[0], size.y / (real)g->n[1], size.z / (real)g->n[2]);
    g->inv_cell = vec3_make(1 / g->cell.x, 1 / g->cell.y, 1 / g->cell.z);
    for (int a = 0; a < 3; a++) {
        g->lo_a[a] = get(g->lo, a);
        g->hi_a[a] = get(g->hi, a);
        g->cell_a[a] = get(g->cell, a);
        g->inv_cell_a[a] = get(g->inv_cell, a);
        g->per_unit[a] = FAST_GRID_BOX_STEPS / (g->cell_a[a] + 2 * g->margin);
        g->frame_step[a] = (g->cell_a[a] + 2 * g->margin) / FAST_GRID_BOX_STEPS;
    }
    g->n_cells = (long)g->n[0] * g->n[1] * g->n[2];
    g->stride[0] = 1;
    g->stride[1] = g->n[0];
    g->stride[2] = (long)g->n[0] * g->n[1];
    /* The cell boundaries, one table for the three axes: the march reads them
     * instead of computing lo_a + k cell_a at every crossing (the same values).
     * A leap looks up to `beyond` cells beyond the grid's faces: the table goes
     * on that far on both sides. */
    int widest = g->n[0] > g->n[1] ? g->n[0] : g->n[1];
    widest = widest > g->n[2] ? widest : g->n[2];
    g->beyond = widest < 255 ? widest + 1 : 255;
    real *planes = malloc(plane_count(g) * sizeof *planes);
    if (!planes)
        goto out_of_memory;
    g->plane[0] = planes + g->beyond;
    g->plane[1] = g->plane[0] + g->n[0] + 1 + 2 * g->beyond;
    g->plane[2] = g->plane[1] + g->n[1] + 1 + 2 * g->beyond;
    for (int a = 0; a < 3; a++)
        for (int k = -g->beyond; k <= g->n[a] + g->beyond; k++)
            g->plane[a][k] = g->lo_a[a] + (real)k * g->cell_a[a];

    /* One pass over the surfaces counts each cell's surfaces and keeps the
     * cells of each (bins); with the offsets summed from the counts, the
     * entries are written from the bins, in increasing index.  A cell lists
     * each surface at most once, so its count fits 32 bits; the same array
     * then holds where the next index of each cell goes. */
    uint32_t *count = calloc((size_t)g->n_cells, sizeof *count);
    g->start = malloc(((size_t)g->n_cells + 1) * sizeof *g->start);
    if (!count || !g->start) {
        free(count);
        goto out_of_memory;
    }
    bin_list bins = {NULL, 0, 0};
    uint32_t *stamp = g->boxes ? malloc((size_t)g->n_cells * sizeof *stamp) : NULL;
    bool binned = !g->boxes || stamp;
    for (long c = 0; c < g->n_cells && stamp; c++)
        stamp[c] = FAST_BOX_NONE;
    for (long q = 0; q < n && binned; q++) {
        /* a surface alone, or a box by its first triangle (its others are listed as that) */
        const uint32_t k = subset ? subset[q] : (uint32_t)q, b = g->boxes ? g->boxes->of[k] : FAST_BOX_NONE;
        if (b == FAST_BOX_NONE)
            binned = bin_surface(g, &g->list->items[k], k, count, &bins, NULL, 0);
        else if (k == g->boxes->box[b].first)
            for (uint32_t t = k; t < k + 12 && binned; t++)
                binned = bin_surface(g, &g->list->items[t], k, count, &bins, stamp, b);
    }
    free(stamp);
    if (!binned) {
        free(count);
        free(bins.at);
        goto out_of_memory;
    }
    uint64_t total = 0;
    for (long c = 0; c < g->n_cells; c++) {
        g->start[c] = (uint32_t)total;
        total += count[c];
        if (total > UINT32_MAX) {
            free(count);
            free(bins.at);
            snprintf(err, err_size, "grid: more than 2^32 cell entries; lower the density or the cell cap");
            return -1;
        }
    }
    g->start[g->n_cells] = (uint32_t)total;
    g->n_refs = (long)total;
    g->refs = malloc((total ? (size_t)total : 1) * sizeof *g->refs);
    if (!g->refs) {
        free(count);
        free(bins.at);
        goto out_of_memory;
    }
    uint32_t *fill = count;
    for (long c = 0; c < g->n_cells; c++)
        fill[c] = g->start[c];
    write_entries(g, &bins, fill);
    free(fill);
    free(bins.at);
    /* the most the build held at once: the grid, the fill array and the bins (and the stamps of a grid with
     * boxes, freed before the entries were made: counted as if held with them, a bound) */
    g->peak_bytes = fast_grid_memory(g) + (size_t)g->n_cells * sizeof *fill * (g->boxes ? 2 : 1) +
                    bins.size * sizeof *bins.at;
    if (leap) {
        g->empty = malloc(8 * (size_t)g->n_cells);
        if (!g->empty)
            goto out_of_memory;
        if (!fast_grid_empty_distances(g))
            goto out_of_memory;
    }
    return 0;

out_of_memory:
    snprintf(err, err_size, "grid: out of memory");
    return -1;
}


int fast_grid_build(fast_grid *g, const surface_list *list, fast_grid_options opt, char *err, size_t err_size)
{
    *g = (fast_grid){.list = list, .mailbox = opt.mailbox, .cull = opt.cull};
    if (!(opt.density > 0) || opt.max_cells < 1 || opt.max_cells > (1L << 30) ||
        opt.prefetch < FAST_GRID_PREFETCH_AUTO || opt.prefetch > FAST_GRID_PREFETCH_OFF || opt.list_up_to < 0) {
        snprintf(err, err_size,
                 "grid: density must be > 0, the cell cap 1 .. 2^30, prefetching 0 .. 2, the list's cost >= 0 "
                 "(got %g, %ld, %d, %d)",
                 opt.density, opt.max_cells, opt.prefetch, opt.list_up_to);
        return -1;
    }
    if ((uint32_t)list->n >= FAST_GRID_BOX) { /* an index at or above it would read as a box's entry */
        snprintf(err, err_size, "grid: %d surfaces, more than the 2^30 - 1 its lists can name", list->n);
        return -1;
    }
    /* The box of every surface with finite bounds; the others are tested for every ray. */
    vec3 lo = vec3_make(REAL_INFINITY, REAL_INFINITY, REAL_INFINITY), hi = vec3_neg(lo), widest = vec3_make(0, 0, 0);
    long binned = 0;
    for (int k = 0; k < list->n; k++) {
        vec3 slo, shi;
        fast_grid_surface_bounds(&list->items[k], &slo, &shi);
        g->spheres = g->spheres || list->items[k].kind == SHAPE_SPHERE;
        if (vec3_is_finite(slo) && vec3_is_finite(shi)) {
            lo = vec3_make(lesser(lo.x, slo.x), lesser(lo.y, slo.y), lesser(lo.z, slo.z));
            hi = vec3_make(greater(hi.x, shi.x), greater(hi.y, shi.y), greater(hi.z, shi.z));
            widest = vec3_make(greater(widest.x, shi.x - slo.x), greater(widest.y, shi.y - slo.y),
                               greater(widest.z, shi.z - slo.z)); /* fast_grid_fit's first look for a large one */
            binned++;
        } else {
            g->n_unbinned++;
        }
    }
    if (g->n_unbinned) {
        g->unbinned = malloc((size_t)g->n_unbinned * sizeof *g->unbinned);
        if (!g->unbinned)
            goto out_of_memory;
        long u = 0;
        for (int k = 0; k < list->n; k++) {
            vec3 slo, shi;
            fast_grid_surface_bounds(&list->items[k], &slo, &shi);
            if (!(vec3_is_finite(slo) && vec3_is_finite(shi)))
                g->unbinned[u++] = (uint32_t)k;
        }
    }
    if (binned == 0)
        return 0; /* no cells: n_cells = 0 and every ray misses the (empty) grid */

    /* snippet: margin */
    /* The margin: rounding moves a computed point (a hit, a cell boundary) by
     * a few units of REAL_EPSILON times the size of its coordinates; every box
     * is widened by far more than that, so a surface is listed in every cell
     * its hits can be computed to lie in.  It also gives a flat scene's box a
     * thickness. */
    g->scale = real_fmax(vec3_max_abs(lo), vec3_max_abs(hi));
    g->margin = 64 * REAL_EPSILON * g->scale;
    if (!(g->margin > 0))
        g->margin = 1; /* every surface is a point at the origin */
    /* end snippet */
    g->lo = widen(lo, -g->margin);
    g->hi = widen(hi, g->margin);
    if (opt.boxes && !fast_boxes_find(&g->boxes, list))
        goto out_of_memory;
    if (!fast_grid_few_units(g, list, opt.list_up_to))
        goto out_of_memory;
    int status = 0;
    if (!g->units) { /* a list (fast_few.c) has every box kept and no cells */
        uint32_t *subset = NULL; /* the surfaces in cells: all but the large ones apart (fast_few.c) */
        long n = list->n;
        if (!fast_grid_fit(g, list, opt, lo, hi, widest, binned, &subset, &n))
            goto out_of_memory;
        status = fast_grid_fill(g, subset, n, opt.leap, err, err_size);
        free(subset);
        if (status == 0)
            status = fast_grid_split(g, opt, err, err_size);
    }
    if (status == 0 && !g->units && !fast_grid_pack(g)) {
        snprintf(err, err_size, "grid: out of memory");
        status = -1;
    }
    if (status == 0 && opt.normals) { /* each triangle's normal, as the hit's record has it */
        g->normal = calloc((size_t)list->n, sizeof *g->normal);
        if (!g->normal)
            goto out_of_memory;
        for (int k = 0; k < list->n; k++)
            if (list->items[k].kind == SHAPE_TRIANGLE)
                g->normal[k] = triangle_normal(&list->items[k].triangle);
    }
    if (status != 0)
        fast_grid_free(g);
    else if (opt.prefetch == FAST_GRID_PREFETCH_AUTO)
        g->prefetch = fast_grid_memory(g) + (size_t)list->n * sizeof(surface) > (size_t)FAST_GRID_PREFETCH_FROM;
    else
        g->prefetch = opt.prefetch == FAST_GRID_PREFETCH_ON;
    return status;

out_of_memory:
    fast_grid_free(g);
    snprintf(err, err_size, "grid: out of memory");
    return -1;
}

void fast_grid_free(fast_grid *g)
{
    free(g->start);
    free(g->refs);
    free(g->lists);
    free(g->unbinned);
    free(g->units);
    free(g->apart);
    free(g->empty);
    free(g->normal);
    fast_boxes_free(g->boxes);
    g->boxes = NULL;
    if (g->plane[0])
        free(g->plane[0] - g->beyond);
    for (long k = 0; k < g->n_subs; k++)
        fast_grid_free(&g->subs[k]);
    free(g->subs);
    g->subs = NULL;
    g->plane[0] = g->plane[1] = g->plane[2] = NULL;
    g->start = g->lists = g->unbinned = g->units = g->apart = NULL;
    g->refs = NULL;
    g->empty = NULL;
    g->normal = NULL;
    g->n_cells = g->n_refs = g->n_unbinned = g->n_units = g->n_apart = g->n_subs = 0;
}

size_t fast_grid_memory(const fast_grid *g)
{
    size_t cells = g->start ? (size_t)g->n_cells + 1 : 0;
    return sizeof *g + (cells + (size_t)g->n_unbinned + (size_t)g->n_units + (size_t)g->n_apart) * sizeof(uint32_t) +
           (size_t)g->n_refs * sizeof(fast_grid_entry) + (g->empty ? 8 * (size_t)g->n_cells : 0) +
           (g->normal ? (size_t)g->list->n * sizeof *g->normal : 0) +
           (g->plane[0] ? plane_count(g) * sizeof(real) : 0) + fast_grid_subs_memory(g) + fast_boxes_memory(g->boxes);
}
