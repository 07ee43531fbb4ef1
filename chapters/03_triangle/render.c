/* render.c - chapter 03's renderer: triangles, coloured by where the ray hits them.
 *
 *   --show=barycentric  colour = (alpha, beta, gamma) as RGB: each vertex is a
 *                       pure red, green or blue, each edge a mix of two;
 *   --show=cracks       rays aimed exactly at the edges and vertices: every
 *                       pixel near an edge casts 16 rays at points of its
 *                       stretch of that edge (cracks.h), grey when all of
 *                       them hit a triangle, red when one slips through.
 *   --triangle          the triangle test: cramer (the lecture's) or watertight.
 *   --cracks=N          before rendering, count the rays from 100 points inside
 *                       an icosahedron aimed at its vertices and at N - 1
 *                       points of every edge that miss it (0: do not count).
 *   --degenerate=N      before rendering, count the false hits of N rays at
 *                       degenerate triangles and N rays in a triangle's plane,
 *                       and the hits lost of about N / 4 proper ones, with
 *                       random rotated and translated data (degenerate_count.h).
 *
 * The built-in scene is one large triangle and an icosahedron; with
 * --show=cracks the camera stands inside the icosahedron.  A scene file's
 * Triangle surfaces are rendered; spheres, boxes and meshes are left to
 * chapter 04, which puts every shape into one list.
 */
#include <stdlib.h>
#include <time.h>

#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "03_triangle/cracks.h"
#include "03_triangle/degenerate_count.h"
#include "03_triangle/icosahedron.h"
#include "renderer.h"
#include "scene_build.h"

enum { SHOW_BARYCENTRIC, SHOW_CRACKS };
static const char *const show_choices[] = {"barycentric", "cracks", NULL};
static const char *const triangle_choices[] = {"cramer", "watertight", NULL};
static int show = SHOW_BARYCENTRIC;
static int test = TRIANGLE_CRAMER;
static int cracks_steps = 0;
static int degenerate_cases = 0;

static const knob knobs[] = {
    {"triangle", KNOB_CHOICE, &test, triangle_choices, "the ray-triangle test"},
    {"show", KNOB_CHOICE, &show, show_choices, "what to colour each pixel by"},
    {"cracks", KNOB_INT, &cracks_steps, NULL,
     "first count the rays at an icosahedron's edges, in steps of 1/V, that slip through (0: off)"},
    {"degenerate", KNOB_INT, &degenerate_cases, NULL,
     "first count false hits at V degenerate triangles and V in-plane rays, and lost hits (0: off)"},
};

/* --show=cracks: how close to an edge, in barycentric units, a pixel is
 * re-aimed at the edge, and the stretch of the edge (as a fraction of its
 * length, to either side) that it stands for: about a pixel's width. */
#define CRACK_EDGE_WIDTH ((real)0.012)
#define CRACK_STRETCH ((real)0.003)
enum { CRACK_RAYS = 16 };

typedef struct {
    camera cam;
    triangle *tris;
    int n;
    color back;
} stage;

/* The closest hit among all triangles: every hit found becomes the far end
 * of the window for the rest, so at the end the nearest one is left.  (The
 * closest hit over all kinds of shapes is chapter 04's subject.) */
static int closest(const stage *s, ray r, triangle_test t, triangle_hit *best)
{
    int found = -1;
    real t_max = REAL_INFINITY;
    for (int k = 0; k < s->n; k++)
        if (triangle_intersect(&s->tris[k], r, 0, t_max, t, best)) {
            t_max = best->t;
            found = k;
        }
    return found;
}

/* snippet: barycentric_color */
static color barycentric_color(triangle_hit h)
{
    real alpha = 1 - h.beta - h.gamma;
    return color_make(alpha, h.beta, h.gamma);
}
/* end snippet */

/* snippet: crack_color */
static color crack_color(const stage *s, ray r, uint64_t *rays)
{
    triangle_hit h;
    /* Where the pixel looks, found with the test that has no cracks. */
    int k = closest(s, r, TRIANGLE_WATERTIGHT, &h);
    if (k < 0)
        return s->back;
    vec3 e0, e1;
    real s0;
    if (!near_edge(&s->tris[k], h.beta, h.gamma, CRACK_EDGE_WIDTH, &e0, &e1, &s0))
        return color_scale(barycentric_color(h), (real)0.08); /* the faces, dark */
    /* The pixel's stretch of the edge, s0 +- CRACK_STRETCH: rays aimed exactly at
     * CRACK_RAYS points of it (all at the vertex when e0 = e1). */
    for (int j = 0; j < CRACK_RAYS; j++) {
        real sj = s0 + CRACK_STRETCH * (2 * (real)j / (CRACK_RAYS - 1) - 1);
        vec3 x = edge_point(e0, e1, real_fmin(1, real_fmax(0, sj)));
        ray aimed = {r.p, vec3_sub(x, r.p)};
        ++*rays;
        if (!hits_any(s->tris, s->n, aimed, (triangle_test)test))
            return color_make(1, 0, 0); /* slipped through a crack */
    }
    return color_make((real)0.25, (real)0.25, (real)0.25);
}
/* end snippet */

static color sample(const void *scene, real u, real v, uint64_t *rays)
{
    const stage *s = scene;
    ray r = camera_ray(&s->cam, u, v);
    ++*rays;
    if (show == SHOW_CRACKS)
        return crack_color(s, r, rays);
    triangle_hit h;
    if (closest(s, r, (triangle_test)test, &h) < 0)
        return s->back;
    return barycentric_color(h);
}

static int add_triangle(scene *desc, vec3 v0, vec3 v1, vec3 v2)
{
    scene_surface surface = {.kind = SURFACE_TRIANGLE, .shader = -1, .v0 = v0, .v1 = v1, .v2 = v2};
    return scene_add_surface(desc, surface);
}

static int add_icosahedron(scene *desc, vec3 centre, real radius)
{
    vec3 v[ICOSAHEDRON_VERTICES];
    triangle faces[ICOSAHEDRON_FACES];
    icosahedron_vertices(centre, radius, v);
    icosahedron_triangles(v, faces);
    for (int f = 0; f < ICOSAHEDRON_FACES; f++)
        if (add_triangle(desc, faces[f].a, faces[f].b, faces[f].c) < 0)
            return -1;
    return 0;
}

/* A large triangle on the left, an icosahedron on the right; or, for
 * --show=cracks, a wide-angle camera inside the unit icosahedron. */
static int builtin(scene *desc)
{
    desc->has_camera = true;
    desc->back_color = color_make((real)0.01, (real)0.01, (real)0.015);
    if (show == SHOW_CRACKS) {
        desc->camera = (scene_camera){
            .kind = CAMERA_PERSPECTIVE,
            .view_point = {0.12, -0.08, 0.15},
            .view_dir = {0.35, 0.25, -1},
            .view_up = {0, 1, 0},
            .proj_distance = 1,
            .view_width = 2.0,
            .view_height = 2.0,
        };
        return add_icosahedron(desc, vec3_make(0, 0, 0), 1);
    }
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 0, 6},
        .view_dir = {0, 0, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 1,
        .view_width = 1.2,
        .view_height = 0.9,
    };
    if (add_triangle(desc, vec3_make(-3, -1.6, 0), vec3_make(-0.2, -1.6, 0), vec3_make(-1.6, 1.8, 0)) < 0)
        return -1;
    return add_icosahedron(desc, vec3_make(1.6, 0, -0.5), (real)1.4);
}

/* --cracks=N: the crack count of the chosen test, on one line. */
static void count_cracks(const char *name)
{
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    crack_count c = icosahedron_cracks(vec3_make(0, 0, 0), 1, 100, cracks_steps, (triangle_test)test);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    fprintf(stderr,
            "%s: --triangle=%s (%s): %ld of %ld rays aimed at edges and vertices from inside slip through, %.3f s\n",
            name, triangle_choices[test], REAL_NAME, c.misses, c.rays, seconds);
}

/* --degenerate=N: false hits at degenerate triangles and by rays in the
 * plane, lost hits on proper triangles, with the chosen test; then the
 * same for triangles of size 1 at distances 0 to 10^6 from the origin. */
static void count_degenerate(const char *name)
{
    degenerate_count c = degenerate_counts(degenerate_cases, (triangle_test)test);
    fprintf(stderr,
            "%s: --triangle=%s (%s): %ld of %ld rays at degenerate triangles hit, %ld false (worst %.3g edge lengths "
            "off); %ld of %ld rays in the plane hit, %ld false (worst %.3g); %ld of %ld clear hits lost\n",
            name, triangle_choices[test], REAL_NAME, c.degenerate_hits, c.degenerate_rays, c.degenerate_false,
            c.degenerate_worst, c.plane_hits, c.plane_rays, c.plane_false, c.plane_worst, c.lost_hits, c.clear_hits);
    for (int e = 0; e <= 6; e++) {
        double distance = e == 0 ? 0 : pow(10, e);
        c = degenerate_counts_at(degenerate_cases, (triangle_test)test, distance);
        fprintf(stderr,
                "%s: --triangle=%s (%s): at distance %g: %ld false hits of %ld rays (worst %.2g edge lengths off the "
                "triangle); %ld of %ld clear hits lost\n",
                name, triangle_choices[test], REAL_NAME, distance, c.degenerate_false + c.plane_false,
                c.degenerate_rays + c.plane_rays, c.worst_off, c.lost_hits, c.clear_hits);
    }
}

static void release(void *prepared)
{
    stage *s = prepared;
    if (s)
        free(s->tris);
    free(s);
}

static void *prepare(const scene *desc, char *err, size_t err_size)
{
    const char *where = scene_name(desc);
    if (cracks_steps < 0 || cracks_steps > 1 << 16) {
        snprintf(err, err_size, "--cracks=%d: must be from 0 (off) to 65536", cracks_steps);
        return NULL;
    }
    if (degenerate_cases < 0 || degenerate_cases > 100000000) {
        snprintf(err, err_size, "--degenerate=%d: must be from 0 (off) to 100000000", degenerate_cases);
        return NULL;
    }
    stage *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, err_size, "%s: out of memory", where);
        return NULL;
    }
    if (!camera_from_scene(&s->cam, desc, err, err_size)) {
        free(s);
        return NULL;
    }
    s->back = desc->back_color;
    s->tris = malloc((size_t)(desc->n_surfaces ? desc->n_surfaces : 1) * sizeof *s->tris);
    if (!s->tris) {
        snprintf(err, err_size, "%s: out of memory", where);
        release(s);
        return NULL;
    }
    for (int k = 0; k < desc->n_surfaces; k++) {
        const scene_surface *surface = &desc->surfaces[k];
        if (surface->kind == SURFACE_TRIANGLE)
            s->tris[s->n++] = (triangle){surface->v0, surface->v1, surface->v2};
    }
    if (cracks_steps > 0)
        count_cracks("03_triangle");
    if (degenerate_cases > 0)
        count_degenerate("03_triangle");
    return s;
}

int main(int argc, char **argv)
{
    const renderer r = {
        .name = "03_triangle",
        .summary = "03_triangle: triangles coloured by their barycentric coordinates (or the cracks between them)",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = FEATURE_TRIANGLES,
        .default_width = 512,
        .default_height = 384,
        .builtin = builtin,
        .prepare = prepare,
        .sample = sample,
        .release = release,
        .pixel_to_image = pixel_to_image,
    };
    return renderer_main(&r, argc, argv);
}
