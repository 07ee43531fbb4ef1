/* fast_query.c - chapter 11's lab: the fast grid as the stage's closest-hit query, counted. */
#include "11_grid/lab/fast_query.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "04_many_shapes/closest_hit.h"

_Thread_local query_tally query_tally_here;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One query, by whichever structure was built, counted in this thread's tally. */
static bool lab_closest_hit(const void *accel, ray r, real t_min, real t_max, hit_record *hit)
{
    const lab_query *lq = accel;
    fast_grid_counts *c = &query_tally_here.counts;
    bool found;
    if (lq->accel == LAB_ACCEL_FAST) {
        found = fast_grid_intersect_counted(&lq->fast, r, t_min, t_max, hit, c);
    } else if (lq->accel == LAB_ACCEL_GRID) {
        grid_counts g = {0, 0};
        found = grid_intersect_counted(&lq->lesson, r, t_min, t_max, hit, &g);
        c->cells += g.cells;
        c->tests += g.tests;
    } else {
        c->tests += (uint64_t)lq->list->n;
        found = surfaces_intersect(lq->list, r, t_min, t_max, hit);
    }
    if (query_tally_here.queries++ == 0)
        query_tally_here.first = *c;
    return found;
}

static void lab_release(void *owned)
{
    lab_query *lq = owned;
    if (lq) {
        grid_free(&lq->lesson);
        fast_grid_free(&lq->fast);
    }
    free(lq);
}

int lab_query_build(const void *knobs, const surface_list *list, const scene *desc, hit_query *q, char *err,
                    size_t err_size)
{
    const fast_knobs *k = knobs;
    lab_query *lq = calloc(1, sizeof *lq);
    if (!lq) {
        snprintf(err, err_size, "%s: out of memory for the grid", scene_name(desc));
        return -1;
    }
    lq->accel = k->accel;
    lq->list = list;
    char why[256] = "";
    double start = now();
    int status = 0;
    if (lq->accel == LAB_ACCEL_FAST) {
        fast_grid_options opt = {.density = (double)k->grid.density,
                                 .max_cells = k->grid.max_cells,
                                 .mailbox = k->mailbox == 0,
                                 .leap = k->leap == 0,
                                 .cull = k->cull == 0,
                                 .split = k->split,
                                 .prefetch = k->prefetch,
                                 .normals = true,
                                 .boxes = k->boxes == 0,
                                 .list_up_to = k->list_up_to};
        status = fast_grid_build(&lq->fast, list, opt, why, sizeof why);
    } else if (lq->accel == LAB_ACCEL_GRID) {
        grid_options opt = {.density = (double)k->grid.density, .max_cells = k->grid.max_cells};
        status = grid_build(&lq->lesson, list, opt, why, sizeof why);
    }
    lq->build_seconds = now() - start;
    if (status != 0) {
        snprintf(err, err_size, "%s: %s", scene_name(desc), why);
        free(lq);
        return -1;
    }
    *q = (hit_query){.closest_hit = lab_closest_hit, .accel = lq, .owned = lq, .release = lab_release};
    return 0;
}
