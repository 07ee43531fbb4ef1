/* render.c - chapter 11's renderer: chapter 10's, with the closest hit through the uniform grid.
 *
 * The stage is chapter 10's (interp_stage.h) with the grid as its closest-hit
 * query (grid_stage.h): every ray, eye, shadow, reflected or refracted, asks
 * the grid in place of the list, and gets the same hit, so the images are
 * chapter 10's byte for byte.  This file adds the knobs of the grid and the
 * report: what the grid cost (build time, memory, cells) and what it did per
 * ray (cells visited, intersection tests), the trace time apart from loading
 * and building.
 *
 * Knobs: chapter 10's (--sphere, --triangle, --shadow-eps, --phong, --depth,
 * --min-weight, --fresnel, --normals, --texture-filter, --below-surface), and
 * --grid-density (cells per surface), --grid-cells (the cap on the cells),
 * --mailbox=on|off, --leap=on|off, --cull=on|off, --accel=grid|list (list:
 * chapter 04's linear scan, that is chapter 10 as it is, for comparison),
 * --show=image|cells|tests (a heat map of the cells visited or the surfaces
 * tested per pixel by its eye ray), --heat-max (the count shown white).
 */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "04_many_shapes/shape_knobs.h"
#include "10_interpolation/face_query.h"
#include "11_grid/grid_stage.h"
#include "11_grid/heat.h"
#include "renderer.h"

static const char *const on_off[] = {"on", "off", NULL};
static const char *const accel_choices[] = {"grid", "list", NULL};
enum { SHOW_IMAGE, SHOW_CELLS, SHOW_TESTS };
static const char *const show_choices[] = {"image", "cells", "tests", NULL};
static int show_choice = SHOW_IMAGE;
static int heat_max = 64;

static const knob grid_knob_list[] = {
    {"grid-density", KNOB_REAL, &grid_settings.density, NULL, "grid cells per surface"},
    {"grid-cells", KNOB_INT, &grid_settings.max_cells, NULL, "the most cells the grid may have"},
    {"mailbox", KNOB_CHOICE, &grid_settings.mailbox, on_off, "skip surfaces already tested along the ray"},
    {"leap", KNOB_CHOICE, &grid_settings.leap, on_off, "cross blocks of empty cells in one step"},
    {"cull", KNOB_CHOICE, &grid_settings.cull, on_off, "test a surface only when the ray meets its box"},
    {"accel", KNOB_CHOICE, &grid_settings.accel, accel_choices, "grid, or chapter 04's linear scan over the list"},
    {"show", KNOB_CHOICE, &show_choice, show_choices, "the image, or each pixel's eye ray's cells visited or tests"},
    {"heat-max", KNOB_INT, &heat_max, NULL, "--show=cells|tests: the count shown white"},
};

/* Per-thread totals, each on its own cache line, so that counting costs no
 * traffic between the cores. */
#define SLOTS 256
typedef struct {
    grid_tally tally;
    char pad[64 - sizeof(grid_tally) % 64];
} slot;

typedef struct {
    shading_view *view;
    slot *slots;
} prepared_view;

static shading_stage the_stage;

static void add_tally(grid_tally *to, const grid_tally *t)
{
    to->queries += t->queries;
    to->counts.cells += t->counts.cells;
    to->counts.tests += t->counts.tests;
    to->counts.culled += t->counts.culled;
}

/* One sample: chapter 10's, with the queries of its rays counted. */
static color sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const prepared_view *pv = prepared;
    grid_tally_here = (grid_tally){0};
    color c = shading_sample(pv->view, u, v, rays);
    int t = omp_get_thread_num();
    if (t < SLOTS) {
        add_tally(&pv->slots[t].tally, &grid_tally_here);
    } else {
        grid_tally *to = &pv->slots[0].tally;
#pragma omp atomic
        to->queries += grid_tally_here.queries;
#pragma omp atomic
        to->counts.cells += grid_tally_here.counts.cells;
#pragma omp atomic
        to->counts.tests += grid_tally_here.counts.tests;
#pragma omp atomic
        to->counts.culled += grid_tally_here.counts.culled;
    }
    if (show_choice == SHOW_IMAGE)
        return c;
    /* The eye ray's march: what the grid does for the rays the camera casts. */
    const grid_counts *eye = &grid_tally_here.first;
    return heat_color(show_choice == SHOW_CELLS ? eye->cells : eye->tests, heat_max);
}

static void release(void *prepared)
{
    prepared_view *pv = prepared;
    if (pv) {
        shading_release(pv->view);
        free(pv->slots);
    }
    free(pv);
}

static void *prepare(const scene *desc, char *err, size_t err_size)
{
    prepared_view *pv = calloc(1, sizeof *pv);
    if (!pv || !(pv->slots = calloc(SLOTS, sizeof *pv->slots))) {
        free(pv);
        snprintf(err, err_size, "%s: out of memory", scene_name(desc));
        return NULL;
    }
    pv->view = shading_prepare(&the_stage, desc, chosen_sphere_formula(), chosen_triangle_test(),
                               err, err_size);
    if (!pv->view) {
        release(pv);
        return NULL;
    }
    return pv;
}

/* The line after the summary: what the grid cost and what it did per ray. */
static void report(const void *prepared, render_stats stats, FILE *out)
{
    const prepared_view *pv = prepared;
    grid_tally sum = {0};
    for (int t = 0; t < SLOTS; t++)
        add_tally(&sum, &pv->slots[t].tally);
    double queries = sum.queries ? (double)sum.queries : 1;
    const surface_list *list = &pv->view->list;
    if (grid_settings.accel == 1) {
        fprintf(out, "11_grid: linear scan over %d surfaces: %d intersection tests per ray; traced in %.3f s\n",
                list->n, list->n, stats.seconds);
        return;
    }
    /* The view's query is chapter 10's face_query around the grid's. */
    const face_query *fq = pv->view->query.accel;
    const grid_query *gq = fq->inner.accel;
    const grid *g = &gq->grid;
    fprintf(out,
            "11_grid: grid %dx%dx%d = %ld cells for %d surfaces (%.2f per cell), %.1f MB, built in %.3f s; "
            "per ray %.2f cells, %.2f intersection tests (%.2f more culled by their boxes); traced in %.3f s\n",
            g->n[0], g->n[1], g->n[2], g->n_cells, list->n,
            g->n_cells ? (double)g->n_refs / (double)g->n_cells : 0.0, (double)grid_memory(g) / 1e6,
            gq->build_seconds, (double)sum.counts.cells / queries, (double)sum.counts.tests / queries,
            (double)sum.counts.culled / queries, stats.seconds);
}

#define MAX_KNOBS 24

int main(int argc, char **argv)
{
    /* snippet: stage */
    the_stage = grid_stage(); /* interp_stage(grid_faces): chapter 10's stage over the grid */
    /* end snippet */
    knob knobs[MAX_KNOBS];
    const int n_grid = (int)(sizeof grid_knob_list / sizeof grid_knob_list[0]);
    if (SHAPE_KNOBS + the_stage.n_knobs + n_grid > MAX_KNOBS) {
        fprintf(stderr, "%s: too many knobs (%d > %d)\n", the_stage.name, SHAPE_KNOBS + the_stage.n_knobs + n_grid,
                MAX_KNOBS);
        return 2;
    }
    int n_knobs = 0;
    for (int k = 0; k < SHAPE_KNOBS; k++) /* --sphere and --triangle first */
        knobs[n_knobs++] = shape_knobs[k];
    for (int k = 0; k < the_stage.n_knobs; k++)
        knobs[n_knobs++] = the_stage.knobs[k];
    for (int k = 0; k < n_grid; k++)
        knobs[n_knobs++] = grid_knob_list[k];
    const renderer r = {
        .name = the_stage.name,
        .summary = the_stage.summary,
        .knobs = knobs,
        .n_knobs = n_knobs,
        .modelled = the_stage.modelled,
        .accelerated = true,
        .default_width = 512,
        .default_height = 512,
        .builtin = the_stage.builtin,
        .prepare = prepare,
        .sample = sample,
        .release = release,
        .report = report,
    };
    return renderer_main(&r, argc, argv);
}
