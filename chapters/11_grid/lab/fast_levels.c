/* fast_levels.c - chapter 11's lab: two levels, a grid of its own for each crowded cell.
 *
 * One resolution cannot suit a whole scene whose surfaces are of very
 * different sizes: on the course's wire-box a floor 100 units wide sets the
 * cells at 4 units, and the wire cube of 2 units with its 152 surfaces sits
 * in a few cells, every one of whose surfaces each ray through them has to
 * cull.  Kalojanov, Billeter and Slusallek ("Two-level grids for ray tracing
 * on GPUs", 2011) give each cell a grid of its own, sized by what it holds;
 * here only the cells that list more than `split` surfaces get one, the
 * most crowded first, within a memory budget.  A surface that spans the
 * cell along two axes (the floor under the wire cube) stays in the cell's
 * list after its grid: in the grid it would fill every cell of a layer and
 * stretch the grid's box over the whole cell.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "11_grid/lab/fast_build.h"

/* A cell's own grid may list each of its surfaces in this many of its cells
 * on average at most, counted by their boxes; beyond that (surfaces that all
 * cross the whole cell, or long thin ones across a fine grid, as at a
 * sphere's pole) the cell keeps its plain list. */
#define MOST_CELLS_PER_SURFACE 16

/* The cells of sub that the boxes of its n surfaces overlap, in all: what
 * its build would test by the separating axis test, and at least what it
 * would list.  sub has its box and its resolution. */
static long box_cells(fast_grid *sub, const uint32_t *subset, long n)
{
    vec3 size = vec3_sub(sub->hi, sub->lo);
    sub->cell = vec3_make(size.x / (real)sub->n[0], size.y / (real)sub->n[1], size.z / (real)sub->n[2]);
    const vec3 m = vec3_make(sub->margin, sub->margin, sub->margin);
    long cells = 0;
    for (long q = 0; q < n; q++) {
        vec3 lo, hi;
        int first[3], last[3];
        fast_grid_entry_bounds(sub, subset[q], &lo, &hi);
        fast_grid_cell_range(sub, vec3_sub(lo, m), vec3_add(hi, m), first, last);
        if (first[0] <= last[0] && first[1] <= last[1] && first[2] <= last[2]) /* else wholly outside */
            cells += (long)(last[0] - first[0] + 1) * (last[1] - first[1] + 1) * (last[2] - first[2] + 1);
    }
    return cells;
}

/* The grid of cell idx of g over the n surfaces `subset` it lists.  Its box
 * is the cell's frame (the cell widened by the margin) cut down to the
 * surfaces' box (widened by the margin): every point where the ray can meet
 * one of them while it is in the cell.  The same margin and scale as g, so
 * that the march's rounding bounds are the same at both levels; g's density
 * and knobs.  0, 1 when the cell is better left as it is, -1 with the
 * problem in err. */
static int build_sub(fast_grid *sub, const fast_grid *g, const uint32_t *subset, long n, const int idx[3],
                     fast_grid_options opt, char *err, size_t err_size)
{
    *sub = (fast_grid){.list = g->list, .mailbox = g->mailbox, .cull = g->cull, .margin = g->margin, .scale = g->scale};
    vec3 lo = vec3_make(REAL_INFINITY, REAL_INFINITY, REAL_INFINITY), hi = vec3_neg(lo);
    for (long q = 0; q < n; q++) {
        vec3 slo, shi;
        fast_grid_entry_bounds(g, subset[q], &slo, &shi);
        lo = vec3_make(real_fmin(lo.x, slo.x), real_fmin(lo.y, slo.y), real_fmin(lo.z, slo.z));
        hi = vec3_make(real_fmax(hi.x, shi.x), real_fmax(hi.y, shi.y), real_fmax(hi.z, shi.z));
    }
    const real s_lo[3] = {lo.x, lo.y, lo.z}, s_hi[3] = {hi.x, hi.y, hi.z};
    real box_lo[3], box_hi[3];
    double extent[3];
    for (int a = 0; a < 3; a++) {
        real frame_lo = g->plane[a][idx[a]] - g->margin, frame_hi = g->plane[a][idx[a] + 1] + g->margin;
        box_lo[a] = real_fmax(s_lo[a] - g->margin, frame_lo);
        box_hi[a] = real_fmin(s_hi[a] + g->margin, frame_hi);
        if (!(box_lo[a] < box_hi[a]))
            return 1;
        extent[a] = (double)box_hi[a] - (double)box_lo[a];
    }
    sub->lo = vec3_make(box_lo[0], box_lo[1], box_lo[2]);
    sub->hi = vec3_make(box_hi[0], box_hi[1], box_hi[2]);
    fast_grid_resolution(extent, n, opt.density, opt.max_cells, sub->n);
    sub->boxes = g->boxes; /* g's, for the bounds of a box's entry while sub is built; cleared after */
    const bool too_many = box_cells(sub, subset, n) > MOST_CELLS_PER_SURFACE * n;
    const int status = too_many ? 1 : fast_grid_fill(sub, subset, n, opt.leap, err, err_size);
    sub->boxes = NULL;
    if (too_many)
        return 1;
    if (status != 0) {
        fast_grid_free(sub);
        return -1;
    }
    return 0;
}

/* Whether entry k (a surface, or a box) spans cell idx of g along two axes
 * or more: its box (widened by the margin) covers the cell's frame there, as
 * a floor covers every cell under it.  Such an entry stays in the cell's own
 * list beside the cell's grid, which then fits the other entries alone. */
static bool spans_cell(const fast_grid *g, uint32_t k, const int idx[3])
{
    vec3 lo, hi;
    fast_grid_entry_bounds(g, k, &lo, &hi);
    const real s_lo[3] = {lo.x, lo.y, lo.z}, s_hi[3] = {hi.x, hi.y, hi.z};
    int covered = 0;
    for (int a = 0; a < 3; a++)
        covered += s_lo[a] - g->margin <= g->plane[a][idx[a]] - g->margin &&
                   s_hi[a] + g->margin >= g->plane[a][idx[a] + 1] + g->margin;
    return covered >= 2;
}

/* A cell that lists more than `split` surfaces, and the grid it got (-1: none). */
typedef struct {
    long cell;
    uint32_t count;
    long sub;
} crowded_cell;

/* The most crowded first (a tie by cell, so that the build does not depend
 * on qsort's order), and by cell. */
static int by_count(const void *x, const void *y)
{
    const crowded_cell *a = x, *b = y;
    if (a->count != b->count)
        return (a->count < b->count) - (a->count > b->count);
    return (a->cell > b->cell) - (a->cell < b->cell);
}
static int by_cell(const void *x, const void *y)
{
    const crowded_cell *a = x, *b = y;
    return (a->cell > b->cell) - (a->cell < b->cell);
}

int fast_grid_split(fast_grid *g, fast_grid_options opt, char *err, size_t err_size)
{
    if (opt.split <= 0 || g->n_cells == 0)
        return 0;
    long n_crowded = 0;
    uint32_t most = 0;
    for (long c = 0; c < g->n_cells; c++) {
        uint32_t count = g->start[c + 1] - g->start[c];
        n_crowded += count > (uint32_t)opt.split;
        most = count > most ? count : most;
    }
    if (n_crowded == 0)
        return 0;
    crowded_cell *crowded = malloc((size_t)n_crowded * sizeof *crowded);
    g->subs = calloc((size_t)n_crowded, sizeof *g->subs);
    uint32_t *subset = malloc((size_t)most * sizeof *subset);
    if (!crowded || !g->subs || !subset) {
        free(crowded);
        free(subset);
        snprintf(err, err_size, "grid: out of memory");
        return -1;
    }
    long k = 0;
    for (long c = 0; c < g->n_cells; c++)
        if (g->start[c + 1] - g->start[c] > (uint32_t)opt.split)
            crowded[k++] = (crowded_cell){.cell = c, .count = g->start[c + 1] - g->start[c], .sub = -1};
    /* The most crowded cells first, while the grids of their own take at
     * most a sixteenth of what the grid takes with one level (at least 1 MB):
     * on a mesh the crowded cells are where thin triangles meet (the poles
     * of a sphere), and their grids cost much and buy little (a quarter took
     * the sphere's build from 0.21 to 0.36 s, for 0.6 % of its rays' time). */
    qsort(crowded, (size_t)n_crowded, sizeof *crowded, by_count);
    size_t budget = fast_grid_memory(g) / 16, spent = 0;
    budget = budget > (1u << 20) ? budget : (1u << 20);
    for (k = 0; k < n_crowded && spent < budget; k++) {
        const long c = crowded[k].cell;
        const int idx[3] = {(int)(c % g->n[0]), (int)(c / g->n[0] % g->n[1]), (int)(c / g->n[0] / g->n[1])};
        long n_rest = 0;
        for (uint32_t q = 0; q < crowded[k].count; q++) {
            uint32_t surface = g->refs[g->start[c] + q].surface;
            if (!spans_cell(g, surface, idx))
                subset[n_rest++] = surface;
        }
        if (n_rest == 0)
            continue;
        fast_grid *sub = &g->subs[g->n_subs];
        int kept = build_sub(sub, g, subset, n_rest, idx, opt, err, err_size);
        if (kept < 0) {
            free(crowded);
            free(subset);
            return -1;
        }
        if (kept == 0 && spent + fast_grid_memory(sub) > budget) {
            fast_grid_free(sub);
            break;
        }
        if (kept == 0) {
            spent += fast_grid_memory(sub);
            crowded[k].sub = g->n_subs++;
        }
    }
    free(subset);
    fast_grid_entry *spanning = malloc(((size_t)most + 1) * sizeof *spanning);
    if (!spanning) {
        free(crowded);
        snprintf(err, err_size, "grid: out of memory");
        return -1;
    }
    /* Each cell's list moves down to where the lists before it end now: a
     * cell with a grid of its own lists that grid first, then the surfaces
     * that span it (copied aside first: the list may move onto itself). */
    qsort(crowded, (size_t)n_crowded, sizeof *crowded, by_cell);
    uint32_t written = 0, from = g->start[0];
    k = 0;
    for (long c = 0; c < g->n_cells; c++) {
        const uint32_t to = g->start[c + 1], count = to - from;
        g->start[c] = written;
        while (k < n_crowded && crowded[k].cell < c)
            k++;
        if (k < n_crowded && crowded[k].cell == c && crowded[k].sub >= 0) {
            const int idx[3] = {(int)(c % g->n[0]), (int)(c / g->n[0] % g->n[1]), (int)(c / g->n[0] / g->n[1])};
            uint32_t n_spanning = 0;
            for (uint32_t q = from; q < to; q++)
                if (spans_cell(g, g->refs[q].surface, idx))
                    spanning[n_spanning++] = g->refs[q];
            g->refs[written++] = (fast_grid_entry){.surface = FAST_GRID_SUB + (uint32_t)crowded[k].sub};
            memcpy(&g->refs[written], spanning, n_spanning * sizeof *spanning);
            written += n_spanning;
        } else {
            memmove(&g->refs[written], &g->refs[from], count * sizeof *g->refs);
            written += count;
        }
        from = to;
    }
    g->start[g->n_cells] = written;
    g->n_refs = written;
    free(crowded);
    free(spanning);
    fast_grid_entry *shrunk = realloc(g->refs, (written ? written : 1) * sizeof *g->refs);
    g->refs = shrunk ? shrunk : g->refs;
    size_t now = fast_grid_memory(g) + most * sizeof *subset;
    g->peak_bytes = now > g->peak_bytes ? now : g->peak_bytes;
    return 0;
}

size_t fast_grid_subs_memory(const fast_grid *g)
{
    size_t bytes = 0;
    for (long k = 0; k < g->n_subs; k++)
        bytes += fast_grid_memory(&g->subs[k]);
    return bytes;
}
