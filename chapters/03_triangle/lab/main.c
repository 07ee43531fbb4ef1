/* main.c - chapter 03's lab: the cracks between triangles, and false hits at degenerate ones.
 *
 * A renderer of chapter 03's stage (triangle_stage.h) with what measures it:
 *   --show=cracks       (the default) the camera inside the unit icosahedron,
 *                       rays aimed exactly at the edges and vertices
 *                       (crack_view.h): red where one slips through;
 *   --show=barycentric  the lesson's picture of the built-in scene;
 *   --triangle          the triangle test: cramer (the lecture's) or watertight;
 *   --cracks=N          before rendering, count the rays from 100 points inside
 *                       an icosahedron aimed at its vertices and at N - 1
 *                       points of every edge that miss it (0: do not count);
 *   --degenerate=N      before rendering, count the false hits of N rays at
 *                       degenerate triangles and N rays in a triangle's plane,
 *                       and the hits lost of about N / 4 proper ones, with
 *                       random rotated and translated data (degenerate_count.h).
 * A scene file's Triangle surfaces are shown as the chosen --show says.
 */
#include <math.h>
#include <time.h>

#include "03_triangle/lab/crack_view.h"
#include "03_triangle/lab/cracks.h"
#include "03_triangle/lab/degenerate_count.h"
#include "03_triangle/scenes/triangle_scene.h"

#define LAB_NAME "03_triangle_lab"

enum { SHOW_CRACKS, SHOW_BARYCENTRIC };
static const char *const show_choices[] = {"cracks", "barycentric", NULL};
static const char *const test_names[] = {"cramer", "watertight"};
static int show = SHOW_CRACKS;
static int cracks_steps = 0;
static int degenerate_cases = 0;

/* --cracks=N: the crack count of the chosen test, on one line. */
static void count_cracks(triangle_test test)
{
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    crack_count c = icosahedron_cracks(vec3_make(0, 0, 0), 1, 100, cracks_steps, test);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    fprintf(stderr,
            "%s: --triangle=%s (%s): %ld of %ld rays aimed at edges and vertices from inside slip through, %.3f s\n",
            LAB_NAME, test_names[test], REAL_NAME, c.misses, c.rays, seconds);
}

/* --degenerate=N: false hits at degenerate triangles and by rays in the
 * plane, lost hits on proper triangles, with the chosen test. */
static void count_degenerate(triangle_test test)
{
    degenerate_count c = degenerate_counts(degenerate_cases, test);
    fprintf(stderr,
            "%s: --triangle=%s (%s): %ld of %ld rays at degenerate triangles hit, %ld false (worst %.3g edge lengths "
            "off); %ld of %ld rays in the plane hit, %ld false (worst %.3g); %ld of %ld clear hits lost\n",
            LAB_NAME, test_names[test], REAL_NAME, c.degenerate_hits, c.degenerate_rays, c.degenerate_false,
            c.degenerate_worst, c.plane_hits, c.plane_rays, c.plane_false, c.plane_worst, c.lost_hits, c.clear_hits);
    /* the same for triangles of size 1 at distances 0 to 10^6 from the origin */
    for (int e = 0; e <= 6; e++) {
        double distance = e == 0 ? 0 : pow(10, e);
        c = degenerate_counts_at(degenerate_cases, test, distance);
        fprintf(stderr,
                "%s: --triangle=%s (%s): at distance %g: %ld false hits of %ld rays (worst %.2g edge lengths off the "
                "triangle); %ld of %ld clear hits lost\n",
                LAB_NAME, test_names[test], REAL_NAME, distance, c.degenerate_false + c.plane_false,
                c.degenerate_rays + c.plane_rays, c.worst_off, c.lost_hits, c.clear_hits);
    }
}

static int builtin(scene *desc) { return show == SHOW_CRACKS ? crack_scene(desc) : triangle_scene(desc); }

static color sample(const void *prepared, real u, real v, uint64_t *rays)
{
    return show == SHOW_CRACKS ? crack_sample(prepared, u, v, rays) : triangle_stage_sample(prepared, u, v, rays);
}

static void *prepare(const void *context, const scene *desc, char *err, size_t err_size)
{
    triangle_stage *s = triangle_stage_prepare(context, desc, err, err_size);
    if (s && cracks_steps > 0)
        count_cracks(s->test);
    if (s && degenerate_cases > 0)
        count_degenerate(s->test);
    return s;
}

/* the knobs' ranges: 0 is off */
static const char *const cracks_range[] = {"0", "65536", NULL}, *const degenerate_range[] = {"0", "100000000", NULL};

int main(int argc, char **argv)
{
    /* The lesson's renderer, with the lab's knobs, scenes and pictures. */
    int test = TRIANGLE_CRAMER; /* the lesson's --triangle */
    knob row;
    renderer r = triangle_stage_renderer(&test, &row);
    const knob knobs[] = {
        r.knobs[0], /* the lesson's --triangle */
        {"show", KNOB_CHOICE, &show, show_choices, "what to colour each pixel by"},
        {"cracks", KNOB_INT, &cracks_steps, cracks_range,
         "first count the rays at an icosahedron's edges, in steps of 1/V, that slip through (0: off)"},
        {"degenerate", KNOB_INT, &degenerate_cases, degenerate_range,
         "first count false hits at V degenerate triangles and V in-plane rays, and lost hits (0: off)"},
    };
    r.name = LAB_NAME;
    r.summary = LAB_NAME ": the rays that slip between triangles (and, on request, the counts of\n"
                         "cracks and of false hits at degenerate triangles)";
    r.knobs = knobs;
    r.n_knobs = sizeof knobs / sizeof knobs[0];
    r.builtin = builtin;
    r.prepare = prepare;
    r.sample = sample;
    return renderer_main(&r, argc, argv);
}
