/* main.c - chapter 11's lab: the renderer of chapter 11 with the fast grid, counters and heat maps.
 *
 * Renders what chapter 11's renderer renders, through --accel=fast (the fast
 * grid, fast_grid.h: the default here), grid (the lesson's) or list (chapter
 * 04's linear scan); all three give the same image byte for byte.  Adds the
 * fast grid's knobs --mailbox, --leap, --cull, --boxes (on|off), --split,
 * --list-up-to, --prefetch (auto|on|off), --show=cells|tests (a heat map of
 * the cells visited or the surfaces tested by each pixel's eye ray),
 * --heat-max (the count shown white), and a report line: what the structure
 * cost and what it did per ray.
 */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "01_camera_rays/pixel.h"
#include "04_many_shapes/renderer/shape_knobs.h"
#include "11_grid/lab/fast_query.h"
#include "11_grid/lab/heat.h"
#include "11_grid/scenes/grid_scene.h"
#include "renderer.h"

static const char *const on_off[] = {"on", "off", NULL};
static const char *const auto_on_off[] = {"auto", "on", "off", NULL}; /* FAST_GRID_PREFETCH_* */
static const char *const accel_choices[] = {"fast", "grid", "list", NULL};
enum { SHOW_IMAGE, SHOW_CELLS, SHOW_TESTS };
static const char *const show_choices[] = {"image", "cells", "tests", NULL};
static const char *const from_zero[] = {"0", NULL}, *const from_one[] = {"1", NULL};

/* What the lab's prepare is given: chapter 11's stage over the lab's query,
 * and the values of every knob, owned by main. */
typedef struct {
    shading_stage stage;
    fast_knobs knobs;
    int show, heat_max; /* --show, --heat-max */
} lab_context;

/* The rows of the lab's own knobs, aimed at *lab; returns how many (LAB_KNOB_ROWS). */
#define LAB_KNOB_ROWS 10
static int lab_knob_rows(lab_context *lab, knob *rows)
{
    fast_knobs *k = &lab->knobs;
    const knob lab_rows[] = {
        {"accel", KNOB_CHOICE, &k->accel, accel_choices,
         "fast grid (the lab's), grid (the lesson's), or chapter 04's linear scan"},
        {"mailbox", KNOB_CHOICE, &k->mailbox, on_off, "fast grid: skip surfaces already tested along the ray"},
        {"leap", KNOB_CHOICE, &k->leap, on_off, "fast grid: cross blocks of empty cells in one step"},
        {"cull", KNOB_CHOICE, &k->cull, on_off, "fast grid: test a surface only when the ray meets its box"},
        {"split", KNOB_INT, &k->split, from_zero,
         "fast grid: a cell listing more surfaces than this gets a grid of its own (0: one level)"},
        {"prefetch", KNOB_CHOICE, &k->prefetch, auto_on_off,
         "fast grid: fetch the next cell and the surfaces to test ahead (auto: grid and surfaces over 4 MB)"},
        {"boxes", KNOB_CHOICE, &k->boxes, on_off, "fast grid: test a box's twelve triangles as one box"},
        {"list-up-to", KNOB_INT, &k->list_up_to, from_zero,
         "fast grid: a scene that costs a ray at most this many triangle tests (a box 1.25, a sphere 4) is a list, "
         "without cells (0: cells always)"},
        {"show", KNOB_CHOICE, &lab->show, show_choices, "the image, or each pixel's eye ray's cells visited or tests"},
        {"heat-max", KNOB_INT, &lab->heat_max, from_one, "--show=cells|tests: the count shown white"},
    };
    int n = (int)(sizeof lab_rows / sizeof lab_rows[0]);
    _Static_assert(sizeof lab_rows / sizeof lab_rows[0] == LAB_KNOB_ROWS, "main's table of knobs holds them all");
    for (int r = 0; r < n; r++)
        rows[r] = lab_rows[r];
    return n;
}

/* Per-thread totals, each on its own cache line, so that counting costs no
 * traffic between the cores. */
#define SLOTS 256
typedef struct {
    query_tally tally;
    char pad[64 - sizeof(query_tally) % 64];
} slot;

typedef struct {
    shading_view *view;
    slot *slots;
    int show, heat_max;
} prepared_view;

static void add_tally(query_tally *to, const query_tally *t)
{
    to->queries += t->queries;
    to->counts.cells += t->counts.cells;
    to->counts.leaps += t->counts.leaps;
    to->counts.tests += t->counts.tests;
    to->counts.culled += t->counts.culled;
}

/* One sample: the stage's, with the queries of its rays counted. */
static color sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const prepared_view *pv = prepared;
    query_tally_here = (query_tally){0};
    color c = shading_sample(pv->view, u, v, rays);
    int t = omp_get_thread_num();
    if (t < SLOTS) {
        add_tally(&pv->slots[t].tally, &query_tally_here);
    } else {
        query_tally *to = &pv->slots[0].tally;
#pragma omp critical(lab_tally)
        add_tally(to, &query_tally_here);
    }
    if (pv->show == SHOW_IMAGE)
        return c;
    /* The eye ray's march: what the structure does for the rays the camera casts. */
    const fast_grid_counts *eye = &query_tally_here.first;
    return heat_color(pv->show == SHOW_CELLS ? eye->cells : eye->tests, pv->heat_max);
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

static void *prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    prepared_view *pv = calloc(1, sizeof *pv);
    if (!pv || !(pv->slots = calloc(SLOTS, sizeof *pv->slots))) {
        free(pv);
        snprintf(err, err_size, "%s: out of memory", scene_name(desc));
        return NULL;
    }
    const lab_context *lab = context;
    pv->show = lab->show;
    pv->heat_max = lab->heat_max;
    const shape_knobs *shapes = &lab->stage.shapes;
    pv->view = shading_prepare(&lab->stage, desc, (sphere_formula)shapes->sphere, (triangle_test)shapes->triangle, err,
                               err_size);
    if (!pv->view) {
        release(pv);
        return NULL;
    }
    return pv;
}

/* The line after the summary: what the structure cost and what it did per ray. */
static void report(const void *prepared, render_stats stats, FILE *out)
{
    const prepared_view *pv = prepared;
    query_tally sum = {0};
    for (int t = 0; t < SLOTS; t++)
        add_tally(&sum, &pv->slots[t].tally);
    double queries = sum.queries ? (double)sum.queries : 1;
    const surface_list *list = &pv->view->list;
    const lab_query *lq = pv->view->query.accel;
    if (lq->accel == LAB_ACCEL_LIST) {
        fprintf(out, "11_grid_lab: linear scan over %d surfaces: %d intersection tests per ray; traced in %.3f s\n",
                list->n, list->n, stats.seconds);
        return;
    }
    const bool fast = lq->accel == LAB_ACCEL_FAST;
    if (fast && lq->fast.units) {
        fprintf(out,
                "11_grid_lab: fast grid: a list of %ld unit%s for %d surface%s (--list-up-to: no cells), %.1f MB, "
                "built in %.3f s; per ray %.2f intersection tests (%.2f more culled by their boxes); "
                "traced in %.3f s\n",
                lq->fast.n_units, lq->fast.n_units == 1 ? "" : "s", list->n, list->n == 1 ? "" : "s",
                (double)fast_grid_memory(&lq->fast) / 1e6,
                lq->build_seconds, (double)sum.counts.tests / queries, (double)sum.counts.culled / queries,
                stats.seconds);
        return;
    }
    const int *n = fast ? lq->fast.n : lq->lesson.n;
    long cells = fast ? lq->fast.n_cells : lq->lesson.n_cells, refs = fast ? lq->fast.n_refs : lq->lesson.n_refs;
    size_t bytes = fast ? fast_grid_memory(&lq->fast) : grid_memory(&lq->lesson);
    /* what only the fast grid has: grids of their own in crowded cells, entries culled by their boxes */
    char subs[64] = "", culled[64] = "", apart[64] = "";
    if (fast) {
        snprintf(subs, sizeof subs, " (%ld with grids of their own)", lq->fast.n_subs);
        if (lq->fast.n_apart) /* the large surfaces tested for every ray (--list-up-to), the cells around the rest */
            snprintf(apart, sizeof apart, "; %ld large unit%s tested apart", lq->fast.n_apart,
                     lq->fast.n_apart == 1 ? "" : "s");
        snprintf(culled, sizeof culled, " (%.2f more culled by their boxes)", (double)sum.counts.culled / queries);
    }
    fprintf(out,
            "11_grid_lab: %s grid %dx%dx%d = %ld cells%s for %d surfaces (%.2f per cell%s), %.1f MB, built in %.3f s; "
            "per ray %.2f cells, %.2f intersection tests%s; traced in %.3f s\n",
            fast ? "fast" : "lesson's", n[0], n[1], n[2], cells, subs, list->n,
            cells ? (double)refs / (double)cells : 0.0, apart, (double)bytes / 1e6, lq->build_seconds,
            (double)sum.counts.cells / queries, (double)sum.counts.tests / queries, culled, stats.seconds);
}

#define MAX_KNOBS (SHAPE_KNOBS + MAX_STAGE_KNOBS + LAB_KNOB_ROWS)

int main(int argc, char **argv)
{
    lab_context lab = {.knobs = FAST_KNOBS_DEFAULT, .show = SHOW_IMAGE, .heat_max = 64};
    knob stage_rows[MAX_STAGE_KNOBS];
    stage_knobs aimed = {0};
    int n_stage = grid_knob_rows(&lab.knobs.grid, stage_rows, &aimed);
    lab.stage = (shading_stage){ /* chapter 11's stage over the lab's query */
        .name = "11_grid_lab", /* its own default output, 11_grid_lab.png, beside the renderer's */
        .modelled = INTERP_MODELLED,
        .shade = shade_interp,
        .shade_knobs = aimed,
        .shapes = SHAPE_KNOBS_DEFAULT,
        .build_query = lab_query_build,
        .query_knobs = &lab.knobs,
        .builtin = grid_scene,
    };
    knob knobs[MAX_KNOBS];
    shape_knob_rows(&lab.stage.shapes, knobs); /* --sphere and --triangle first */
    int n_knobs = SHAPE_KNOBS;
    for (int k = 0; k < n_stage; k++) /* the lesson's, but its --accel: the lab's has three choices */
        if (strcmp(stage_rows[k].name, "accel") != 0)
            knobs[n_knobs++] = stage_rows[k];
    n_knobs += lab_knob_rows(&lab, knobs + n_knobs);
    const renderer r = {
        .name = lab.stage.name,
        .summary = "11_grid_lab: chapter 11's renderer with a choice of closest-hit query (the fast grid, the "
                   "lesson's grid or the linear scan) and what each cost per ray",
        .knobs = knobs,
        .n_knobs = n_knobs,
        .modelled = lab.stage.modelled,
        .accelerated = true,
        .default_width = 512,
        .default_height = 512,
        .builtin = lab.stage.builtin,
        .prepare = prepare,
        .context = &lab,
        .sample = sample,
        .release = release,
        .report = report,
        .pixel_to_image = pixel_to_image,
    };
    return renderer_main(&r, argc, argv);
}
