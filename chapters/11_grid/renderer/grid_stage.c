/* grid_stage.c - chapter 11: the grid as the closest-hit query of chapter 10's stage. */
#include "11_grid/renderer/grid_stage.h"

#include <stdio.h>
#include <stdlib.h>

#include "04_many_shapes/closest_hit.h"

static const char *const accel_choices[] = {"grid", "list", NULL};
static const char *const density_range[] = {">0", NULL}, *const cells_range[] = {"1", "1073741824", NULL}; /* 2^30 */

int grid_knob_rows(grid_knobs *k, knob *rows, stage_knobs *aimed)
{
    int n = interp_knob_rows(&k->interp, rows, aimed); /* chapters 06-10's first */
    rows[n++] = (knob){"grid-density", KNOB_REAL, &k->density, density_range, "grid cells per surface, above 0"};
    rows[n++] = (knob){"grid-cells", KNOB_INT, &k->max_cells, cells_range, "the cap on the grid's cells, 1 to 2^30"};
    rows[n++] = (knob){"accel", KNOB_CHOICE, &k->accel, accel_choices, "grid, or chapter 04's linear scan"};
    return n;
}

static bool grid_closest_hit(const void *g, ray r, real t_min, real t_max, hit_record *hit)
{
    return grid_intersect(g, r, t_min, t_max, hit);
}

static void grid_release(void *g) { grid_free(g), free(g); }

int grid_query(const void *knobs, const surface_list *list, const scene *desc, hit_query *q, char *err,
               size_t err_size)
{
    const grid_knobs *k = knobs;
    if (k->accel == GRID_ACCEL_LIST) { /* chapter 04's linear scan */
        *q = (hit_query){.closest_hit = closest_hit_linear, .accel = list};
        return 0;
    }
    grid *g = malloc(sizeof *g);
    char why[256];
    grid_options opt = {.density = (double)k->density, .max_cells = k->max_cells};
    if (!g || grid_build(g, list, opt, why, sizeof why) != 0) {
        snprintf(err, err_size, "%s: %s", scene_name(desc), g ? why : "out of memory for the grid");
        free(g);
        return -1;
    }
    *q = (hit_query){.closest_hit = grid_closest_hit, .accel = g, .owned = g, .release = grid_release};
    return 0;
}
