/* grid_stage.c - chapter 11: the grid as the closest-hit query of chapter 10's stage. */
#include "11_grid/grid_stage.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "04_many_shapes/closest_hit.h"
#include "10_interpolation/interp_stage.h"
#include "11_grid/grid_scene.h"

grid_knobs grid_settings = {
    .density = (real)GRID_DEFAULT_DENSITY,
    .max_cells = (int)GRID_DEFAULT_MAX_CELLS,
};

_Thread_local grid_tally grid_tally_here;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static bool grid_closest_hit(const void *accel, ray r, real t_min, real t_max, hit_record *hit)
{
    const grid_query *gq = accel;
    bool found = grid_intersect_counted(&gq->grid, r, t_min, t_max, hit, &grid_tally_here.counts);
    if (grid_tally_here.queries++ == 0)
        grid_tally_here.first = grid_tally_here.counts;
    return found;
}

/* Chapter 04's linear scan, counted: every surface is tested. */
static bool list_closest_hit(const void *accel, ray r, real t_min, real t_max, hit_record *hit)
{
    const surface_list *list = accel;
    grid_tally_here.counts.tests += (uint64_t)list->n;
    if (grid_tally_here.queries++ == 0)
        grid_tally_here.first = grid_tally_here.counts;
    return surfaces_intersect(list, r, t_min, t_max, hit);
}

static void grid_query_release(void *owned)
{
    grid_query *gq = owned;
    if (gq)
        grid_free(&gq->grid);
    free(gq);
}

int grid_query_build(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size)
{
    const char *where = scene_name(desc);
    if (grid_settings.accel == 1) {
        *q = (hit_query){.closest_hit = list_closest_hit, .accel = list};
        return 0;
    }
    grid_query *gq = calloc(1, sizeof *gq);
    if (!gq) {
        snprintf(err, err_size, "%s: out of memory for the grid", where);
        return -1;
    }
    grid_options opt = {.density = (double)grid_settings.density,
                        .max_cells = grid_settings.max_cells,
                        .mailbox = grid_settings.mailbox == 0,
                        .leap = grid_settings.leap == 0,
                        .cull = grid_settings.cull == 0};
    char why[256];
    double start = now();
    if (grid_build(&gq->grid, list, opt, why, sizeof why) != 0) {
        snprintf(err, err_size, "%s: %s", where, why);
        free(gq);
        return -1;
    }
    gq->build_seconds = now() - start;
    *q = (hit_query){.closest_hit = grid_closest_hit, .accel = gq, .owned = gq, .release = grid_query_release};
    return 0;
}

/* snippet: grid_faces */
int grid_faces(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size)
{
    return face_query_build(list, desc, grid_query_build, q, err, err_size);
}

shading_stage grid_stage(void)
{
    shading_stage stage = interp_stage(grid_faces); /* chapter 10's stage, the grid as its query */
    stage.name = "11_grid";
    stage.summary = "11_grid: the closest hit through a uniform grid (3D-DDA), shaded as in chapter 10";
    stage.builtin = grid_scene;
    return stage;
}
/* end snippet */
