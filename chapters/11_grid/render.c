/* render.c - chapter 11's renderer: the closest hit through the uniform grid.
 *
 * The surfaces, the eye rays and the colours are chapter 04's: each pixel
 * shows the flat colour of the first surface its ray hits.  The one change
 * is the closest-hit query: grid_intersect over the grid in place of
 * surfaces_intersect over the list, the same signature with the grid in
 * place of the list, and the same hit, so the images are byte for byte
 * chapter 04's.  When the shading chapters (05-10) land, this renderer moves
 * onto the last of them: the grid then goes into that chapter's tracing
 * context as its closest_hit_fn, in one assignment, and this file keeps
 * only the knobs and the report.
 *
 * Knobs: --grid-density (cells per surface), --grid-cells (the cap on the
 * cells), --mailbox=on|off, --leap=on|off, --cull=on|off, --accel=grid|list (list: chapter 04's linear
 * scan, for comparison), --show=image|cells|tests (a heat map of the cells
 * visited or the surfaces tested per pixel), --heat-max (the count shown
 * white), and chapter 02's --sphere and chapter 03's --triangle.
 */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <time.h>

#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "04_many_shapes/closest_hit.h"
#include "04_many_shapes/flat_shading.h"
#include "04_many_shapes/scene_surfaces.h"
#include "11_grid/grid.h"
#include "11_grid/heat.h"
#include "renderer.h"
#include "scene_build.h"

static const char *const sphere_choices[] = {"robust", "textbook", NULL};
static const sphere_formula sphere_formulas[] = {SPHERE_ROBUST, SPHERE_TEXTBOOK};
static int sphere_choice = 0;
static const char *const triangle_choices[] = {"cramer", "watertight", NULL};
static const triangle_test triangle_tests[] = {TRIANGLE_CRAMER, TRIANGLE_WATERTIGHT};
static int triangle_choice = TRIANGLE_TEST_DEFAULT; /* triangle_choices is in the order of the enum */
static real density = (real)GRID_DEFAULT_DENSITY;
static int max_cells = (int)GRID_DEFAULT_MAX_CELLS;
static const char *const on_off[] = {"on", "off", NULL};
static int mailbox_choice = 0;
static int leap_choice = 0;
static int cull_choice = 0;
static const char *const accel_choices[] = {"grid", "list", NULL};
static int accel_choice = 0;
enum { SHOW_IMAGE, SHOW_CELLS, SHOW_TESTS };
static const char *const show_choices[] = {"image", "cells", "tests", NULL};
static int show_choice = SHOW_IMAGE;
static int heat_max = 64;

static const knob knobs[] = {
    {"sphere", KNOB_CHOICE, &sphere_choice, sphere_choices, "ray-sphere formula (chapter 02)"},
    {"triangle", KNOB_CHOICE, &triangle_choice, triangle_choices, "ray-triangle test (chapter 03)"},
    {"grid-density", KNOB_REAL, &density, NULL, "grid cells per surface"},
    {"grid-cells", KNOB_INT, &max_cells, NULL, "the most cells the grid may have"},
    {"mailbox", KNOB_CHOICE, &mailbox_choice, on_off, "skip surfaces already tested along the ray"},
    {"leap", KNOB_CHOICE, &leap_choice, on_off, "cross blocks of empty cells in one step"},
    {"cull", KNOB_CHOICE, &cull_choice, on_off, "test a surface only when the ray meets its box"},
    {"accel", KNOB_CHOICE, &accel_choice, accel_choices, "grid, or chapter 04's linear scan over the list"},
    {"show", KNOB_CHOICE, &show_choice, show_choices, "the image, or cells visited or surfaces tested per pixel"},
    {"heat-max", KNOB_INT, &heat_max, NULL, "--show=cells|tests: the count shown white"},
};

/* Per-thread counters, each on its own cache line, so that counting costs
 * no traffic between the cores. */
#define SLOTS 256
typedef struct {
    grid_counts counts;
    char pad[64 - sizeof(grid_counts)];
} slot;

typedef struct {
    camera cam;
    surface_list list;
    grid grid;
    double build_seconds;
    const scene *desc;
    slot *slots;
} stage;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static color sample(const void *prepared, real u, real v, uint64_t *rays)
{
    const stage *st = prepared;
    ++*rays;
    ray r = camera_ray(&st->cam, u, v);
    if (accel_choice == 1) /* the linear scan: chapter 04 as it is */
        return trace_flat(&st->list, st->desc, r, 0, REAL_INFINITY);
    grid_counts counts = {0, 0, 0};
    hit_record hit;
    /* snippet: swap */
    bool found = grid_intersect_counted(&st->grid, r, 0, REAL_INFINITY, &hit, &counts);
    /* end snippet */
    int t = omp_get_thread_num();
    if (t < SLOTS) {
        st->slots[t].counts.cells += counts.cells;
        st->slots[t].counts.tests += counts.tests;
        st->slots[t].counts.culled += counts.culled;
    } else {
#pragma omp atomic
        st->slots[0].counts.cells += counts.cells;
#pragma omp atomic
        st->slots[0].counts.tests += counts.tests;
#pragma omp atomic
        st->slots[0].counts.culled += counts.culled;
    }
    if (show_choice != SHOW_IMAGE)
        return heat_color(show_choice == SHOW_CELLS ? counts.cells : counts.tests, heat_max);
    return found ? flat_color(st->desc, &hit) : st->desc->back_color;
}

static void release(void *prepared)
{
    stage *st = prepared;
    if (st) {
        grid_free(&st->grid);
        surface_list_free(&st->list);
        free(st->slots);
    }
    free(st);
}

static void *prepare(const scene *desc, char *err, size_t err_size)
{
    const char *where = desc->path ? desc->path : "built-in scene";
    stage *st = calloc(1, sizeof *st);
    if (!st || !(st->slots = calloc(SLOTS, sizeof *st->slots))) {
        free(st);
        snprintf(err, err_size, "%s: out of memory", where);
        return NULL;
    }
    st->desc = desc;
    surface_list_init(&st->list, sphere_formulas[sphere_choice], triangle_tests[triangle_choice]);
    if (!camera_from_scene(&st->cam, desc, err, err_size) ||
        surface_list_from_scene(&st->list, desc, err, err_size) != 0) {
        release(st);
        return NULL;
    }
    if (accel_choice == 0) {
        grid_options opt = {.density = (double)density,
                            .max_cells = max_cells,
                            .mailbox = mailbox_choice == 0,
                            .leap = leap_choice == 0,
                            .cull = cull_choice == 0};
        double start = now();
        char why[256];
        if (grid_build(&st->grid, &st->list, opt, why, sizeof why) != 0) {
            snprintf(err, err_size, "%s: %s", where, why);
            release(st);
            return NULL;
        }
        st->build_seconds = now() - start;
    }
    return st;
}

/* The line after the summary: what the grid cost and what it did per ray. */
static void report(const void *prepared, render_stats stats, FILE *out)
{
    const stage *st = prepared;
    double rays = stats.rays ? (double)stats.rays : 1;
    if (accel_choice == 1) {
        fprintf(out, "11_grid: linear scan over %d surfaces: %d intersection tests per ray; traced in %.3f s\n",
                st->list.n, st->list.n, stats.seconds);
        return;
    }
    grid_counts sum = {0, 0, 0};
    for (int t = 0; t < SLOTS; t++) {
        sum.cells += st->slots[t].counts.cells;
        sum.tests += st->slots[t].counts.tests;
        sum.culled += st->slots[t].counts.culled;
    }
    const grid *g = &st->grid;
    fprintf(out,
            "11_grid: grid %dx%dx%d = %ld cells for %d surfaces (%.2f per cell), %.1f MB, built in %.3f s; "
            "per ray %.2f cells, %.2f intersection tests (%.2f more culled by their boxes); traced in %.3f s\n",
            g->n[0], g->n[1], g->n[2], g->n_cells, st->list.n,
            g->n_cells ? (double)g->n_refs / (double)g->n_cells : 0.0, (double)grid_memory(g) / 1e6,
            st->build_seconds, (double)sum.cells / rays, (double)sum.tests / rays, (double)sum.culled / rays,
            stats.seconds);
}

/* snippet: builtin */
/* What grids are for, and where they break: a floor of two huge triangles
 * under a torus of 2304 small ones and a spiral of 1000 small spheres, one
 * big sphere among them, all in flat colours (the torus in RGBNormals). */
static int builtin(scene *desc)
{
    desc->has_camera = true;
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 4.5, 9},
        .view_dir = {0, -0.45, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 2,
        .view_width = 2,
        .view_height = 2,
    };
    desc->back_color = color_make((real)0.55, (real)0.7, (real)0.9);
    const color colors[] = {
        {0.45, 0.45, 0.4}, {0.8, 0.15, 0.1}, {0.1, 0.25, 0.8}, {0.15, 0.6, 0.2}, {0.95, 0.8, 0.1}, {0.6, 0.2, 0.7},
    };
    enum { N_COLORS = sizeof colors / sizeof colors[0] };
    int shader[N_COLORS + 1];
    for (int k = 0; k < N_COLORS; k++) {
        scene_shader s = scene_default_shader(SHADER_LAMBERTIAN);
        s.diffuse_color = colors[k];
        shader[k] = scene_add_shader(desc, s);
    }
    shader[N_COLORS] = scene_add_shader(desc, scene_default_shader(SHADER_RGB_NORMALS));
    for (int k = 0; k <= N_COLORS; k++)
        if (shader[k] < 0)
            return -1;

    /* The floor: two triangles 40 units wide, far beyond everything else. */
    const vec3 floor[4] = {{-20, 0, -20}, {20, 0, -20}, {20, 0, 20}, {-20, 0, 20}};
    if (scene_add_surface(desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = shader[0], .v0 = floor[0],
                                                .v1 = floor[2], .v2 = floor[1]}) < 0 ||
        scene_add_surface(desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = shader[0], .v0 = floor[0],
                                                .v1 = floor[3], .v2 = floor[2]}) < 0)
        return -1;
    /* A torus of radii 1.3 and 0.45 about the y axis, 48 x 24 quads. */
    const int nu = 48, nv = 24;
    const double R = 1.3, r = 0.45, pi = 3.14159265358979323846;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            vec3 q[4];
            for (int c = 0; c < 4; c++) {
                double u = 2 * pi * (i + (c == 1 || c == 2)) / nu, v = 2 * pi * (j + (c >= 2)) / nv;
                q[c] = vec3_make((real)((R + r * cos(v)) * cos(u)), (real)(1 + r * sin(v)),
                                 (real)((R + r * cos(v)) * sin(u)));
            }
            scene_surface t = {.kind = SURFACE_TRIANGLE, .shader = shader[N_COLORS]};
            t.v0 = q[0], t.v1 = q[2], t.v2 = q[1];
            if (scene_add_surface(desc, t) < 0)
                return -1;
            t.v0 = q[0], t.v1 = q[3], t.v2 = q[2];
            if (scene_add_surface(desc, t) < 0)
                return -1;
        }
    /* 1000 small spheres on a golden-angle spiral around it. */
    for (int k = 0; k < 1000; k++) {
        double a = k * 2.39996322972865332, rho = 2.2 + 3.2 * sqrt(k / 1000.0);
        scene_surface s = {.kind = SURFACE_SPHERE, .shader = shader[1 + k % (N_COLORS - 1)],
                           .center = {(real)(rho * cos(a)), (real)(0.12 + 0.004 * (k % 50)),
                                      (real)(rho * sin(a))},
                           .radius = (real)0.12};
        if (scene_add_surface(desc, s) < 0)
            return -1;
    }
    /* One big sphere behind the torus. */
    scene_surface big = {.kind = SURFACE_SPHERE, .shader = shader[2], .center = {0, 1.6, -4.5}, .radius = 1.6};
    return scene_add_surface(desc, big) < 0 ? -1 : 0;
}
/* end snippet */

int main(int argc, char **argv)
{
    const renderer r = {
        .name = "11_grid",
        .summary = "11_grid: the closest hit through a uniform grid (3D-DDA), flat colours as in chapter 04",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS,
        .default_width = 512,
        .default_height = 512,
        .builtin = builtin,
        .prepare = prepare,
        .sample = sample,
        .release = release,
        .pixel_to_image = pixel_to_image,
        .report = report,
    };
    return renderer_main(&r, argc, argv);
}
