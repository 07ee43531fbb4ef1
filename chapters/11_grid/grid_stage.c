/* grid_stage.c - chapter 11: the grid as the closest-hit query of chapter 10's stage. */
#include "11_grid/grid_stage.h"

#include <stdio.h>
#include <stdlib.h>

#include "04_many_shapes/closest_hit.h"
#include "10_interpolation/interp_stage.h"
#include "11_grid/scenes/grid_scene.h"

grid_knobs grid_settings = {.density = (real)GRID_DEFAULT_DENSITY, .max_cells = (int)GRID_DEFAULT_MAX_CELLS};

const knob grid_knob_rows[GRID_KNOBS] = {
    {"grid-density", KNOB_REAL, &grid_settings.density, NULL, "grid cells per surface"},
    {"grid-cells", KNOB_INT, &grid_settings.max_cells, NULL, "the most cells the grid may have"},
};

static const char *const accel_choices[] = {"grid", "list", NULL};

static bool grid_closest_hit(const void *g, ray r, real t_min, real t_max, hit_record *hit)
{
    return grid_intersect(g, r, t_min, t_max, hit);
}

static void grid_release(void *g) { grid_free(g), free(g); }

/* snippet: grid_query */
int grid_query(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size)
{
    if (grid_settings.accel == GRID_ACCEL_LIST)
        return hit_query_linear(list, desc, q, err, err_size);
    grid *g = malloc(sizeof *g);
    char why[256];
    grid_options opt = {.density = (double)grid_settings.density, .max_cells = grid_settings.max_cells};
    if (!g || grid_build(g, list, opt, why, sizeof why) != 0) {
        snprintf(err, err_size, "%s: %s", scene_name(desc), g ? why : "out of memory for the grid");
        free(g);
        return -1;
    }
    *q = (hit_query){.closest_hit = grid_closest_hit, .accel = g, .owned = g, .release = grid_release};
    return 0;
}

shading_stage grid_stage(void)
{
    /* chapter 10's knobs, then the grid's */
    static knob rows[MAX_STAGE_KNOBS];
    shading_stage stage = interp_stage(grid_query); /* chapter 10's stage, the grid as its query */
    int n = 0;
    for (int k = 0; k < stage.n_knobs; k++)
        rows[n++] = stage.knobs[k];
    for (int k = 0; k < GRID_KNOBS; k++)
        rows[n++] = grid_knob_rows[k];
    rows[n++] = (knob){"accel", KNOB_CHOICE, &grid_settings.accel, accel_choices,
                       "grid, or chapter 04's linear scan over the list"};
    stage.name = "11_grid";
    stage.summary = "11_grid: the closest hit through a uniform grid (3D-DDA), shaded as in chapter 10";
    stage.knobs = rows;
    stage.n_knobs = n;
    stage.builtin = grid_scene;
    stage.accelerated = true;
    return stage;
}
/* end snippet */
