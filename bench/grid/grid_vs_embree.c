/* grid_vs_embree.c - chapter 11's fast grid (its lab) against chapter 04's linear scan and
 * Intel Embree 3, on exactly the same rays.  Built and run by `make bench-grid`
 * only (bench/grid/grid.mk); never part of `make` or `make test`.
 *
 *     grid_vs_embree MESH.obj | sphere:N   [--size 512] [--linear-rows K] [--random] [--cramer] [--split N]
 *                    [--prefetch auto|on|off]
 *
 * One primary ray per pixel of a WxW image looking at the mesh (or, with
 * --random, as many incoherent rays: see make_random_rays); every
 * vertex and every ray is rounded to float first, so Embree (which works in
 * float) and the grid (in `real`) get the same numbers.  Prints million rays
 * per second for each on 1 thread (from the CPU time of that thread, which
 * on a shared machine counts only the time it ran), the 2-thread speed-ups
 * (from wall-clock time), the same by kind of ray (those that hit the
 * mesh, those that cross its box and miss it, those that miss its box), the
 * build times and the memory of the grid and of Embree's BVH (both without
 * the mesh itself), the grid's knobs side by side, and how often the three
 * agree on the triangle hit.  Embree runs twice: as built by default, and
 * with RTC_SCENE_FLAG_ROBUST, its mode that avoids the optimisations that
 * cost accuracy (rays through the edges of neighbouring triangles), the
 * nearer to the grid's guarantee of the two.  The grid answers as rtcIntersect1 does, with the hit
 * alone (its triangle, t and barycentric coordinates: fast_grid_closest),
 * without the record that a renderer makes from it (the linear scan makes
 * the record).  The triangle test is the renderers' default, the
 * watertight one (--cramer: chapter 03's Cramer's rule); the grid has two
 * levels from FAST_GRID_DEFAULT_SPLIT surfaces in a cell (--split N; 0: one) and prefetches by its
 * size (--prefetch, fast_grid.h).  The linear scan traces every K-th row only (K =
 * --linear-rows; 0 skips it) and its rate is that of the rows it traced.
 */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <embree3/rtcore.h>

#include "04_many_shapes/closest_hit.h"
#include "11_grid/lab/fast_grid.h"
#include "threads.h"
#include "workload.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- Embree ---------------------------------------------------------------------------- */

static long long embree_bytes, embree_peak;
static bool monitor(void *user, ssize_t bytes, bool post)
{
    (void)user;
    (void)post;
#pragma omp critical(embree_monitor)
    {
        embree_bytes += bytes;
        if (embree_bytes > embree_peak)
            embree_peak = embree_bytes;
    }
    return true;
}

static RTCScene embree_scene(RTCDevice device, const float_mesh *fm, enum RTCSceneFlags flags)
{
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, flags);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    /* Shared buffers: the mesh stays ours, as the surface list stays the grid's;
     * Embree's memory is then its BVH alone.  (Vertex buffers need 4 spare bytes
     * at the end for Embree's SSE loads; malloc'ed with room.) */
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, fm->v, 0, 3 * sizeof(float),
                               (size_t)fm->n_v);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, fm->tri, 0, 3 * sizeof(unsigned),
                               (size_t)fm->n_tri);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
    return scene;
}

/* ---- tracing ---------------------------------------------------------------------------- */

enum { LINEAR, GRID, EMBREE };

typedef struct {
    const surface_list *list;
    const fast_grid *g;
    RTCScene scene;
    const float_ray *rays;
    int size;
    int *prim; /* per ray: the triangle hit, or -1 */
} tracer;

/* CPU seconds of the calling thread: on a shared machine, the time it ran,
 * not the time it waited for a core. */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The triangle that ray *fr hits by `method`, or -1. */
static inline int trace_one(const tracer *tr, int method, const float_ray *fr, struct RTCIntersectContext *context)
{
    if (method == EMBREE) {
        struct RTCRayHit rh;
        memset(&rh, 0, sizeof rh);
        rh.ray.org_x = fr->o[0], rh.ray.org_y = fr->o[1], rh.ray.org_z = fr->o[2];
        rh.ray.dir_x = fr->d[0], rh.ray.dir_y = fr->d[1], rh.ray.dir_z = fr->d[2];
        rh.ray.tnear = 0;
        rh.ray.tfar = INFINITY;
        rh.ray.mask = (unsigned)-1;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(tr->scene, context, &rh);
        return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : (int)rh.hit.primID;
    }
    if (method == GRID) {
        fast_grid_hit hit;
        return fast_grid_closest(tr->g, to_ray(fr), 0, REAL_INFINITY, &hit) ? hit.surface : -1;
    }
    hit_record hit;
    return surfaces_intersect(tr->list, to_ray(fr), 0, REAL_INFINITY, &hit) ? hit.surface : -1;
}

/* Traces rows 0, step, 2 step, ... with `threads` threads; returns the
 * seconds: CPU seconds of the calling thread when `cpu` (1 thread only),
 * else wall-clock seconds. */
static double trace(const tracer *tr, int method, int step, int threads, bool cpu)
{
    double start = cpu ? cpu_now() : now();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = 0; j < tr->size; j += step) {
        struct RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (int i = 0; i < tr->size; i++) {
            long k = (long)j * tr->size + i;
            tr->prim[k] = trace_one(tr, method, &tr->rays[k], &context);
        }
    }
    return (cpu ? cpu_now() : now()) - start;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of `runs` timings (at most 15; the machine is shared: the median
 * is the typical undisturbed run, not the luckiest). */
static double best_of(const tracer *tr, int method, int step, int threads, bool cpu, int runs)
{
    double t[15];
    int n = runs < 15 ? runs : 15;
    for (int r = 0; r < n; r++)
        t[r] = trace(tr, method, step, threads, cpu);
    qsort(t, (size_t)n, sizeof *t, compare_doubles);
    return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

/* What ray k meets: 0 the mesh (Embree's answer), 1 the mesh's box but not
 * the mesh, 2 not even its box (the slab test, in double on the float ray). */
static int kind_of(const float_ray *r, int embree_prim, const float lo[3], const float hi[3])
{
    if (embree_prim >= 0)
        return 0;
    double t0 = 0, t1 = INFINITY;
    for (int a = 0; a < 3; a++) {
        double near = ((double)lo[a] - r->o[a]) / r->d[a], far = ((double)hi[a] - r->o[a]) / r->d[a];
        t0 = fmax(t0, fmin(near, far));
        t1 = fmin(t1, fmax(near, far));
    }
    return t0 <= t1 ? 1 : 2;
}

/* Each kind of ray (kind_of) traced alone, in the rays' order, 1 thread,
 * the grid and Embree in turn, medians of `runs`: where the grid's time goes
 * against Embree's.  Then each ray traced twice in a row: the second trace
 * finds what the first read in the caches, so twice less once is a ray's
 * time at warm caches, and once less that its wait for memory. */
static void print_by_kind(const tracer *tr, const int *embree_prim, const float_mesh *fm, long n_rays, int runs)
{
    static const char *const names[3] = {"hit the mesh", "cross its box, miss it", "miss its box"};
    float lo[3], hi[3];
    mesh_box(fm, lo, hi);
    float_ray *chosen = malloc((size_t)n_rays * sizeof *chosen);
    int n_runs = runs < 15 ? runs : 15;
    printf("  by kind of ray (1 thread): share of the rays, grid and Embree ns per ray, grid / Embree, the same at"
           " warm caches; the grid per ray: cells, leaps, tests, culled\n");
    for (int kind = 0; kind < 3 && chosen; kind++) {
        long n = 0;
        for (long k = 0; k < n_rays; k++)
            if (kind_of(&tr->rays[k], embree_prim[k], lo, hi) == kind)
                chosen[n++] = tr->rays[k];
        if (n == 0)
            continue;
        double t[2][2][15]; /* [once, twice][grid, Embree][run] */
        for (int r = 0; r < n_runs; r++)
            for (int times = 1; times <= 2; times++)
                for (int method = GRID; method <= EMBREE; method++) {
                    struct RTCIntersectContext context;
                    rtcInitIntersectContext(&context);
                    double start = cpu_now();
                    for (long k = 0; k < n; k++)
                        for (int again = 0; again < times; again++)
                            trace_one(tr, method, &chosen[k], &context);
                    t[times - 1][method - GRID][r] = cpu_now() - start;
                }
        double median[2][2];
        for (int times = 0; times < 2; times++)
            for (int m = 0; m < 2; m++) {
                qsort(t[times][m], (size_t)n_runs, sizeof t[times][m][0], compare_doubles);
                median[times][m] = t[times][m][n_runs / 2];
            }
        double grid = median[0][0], embree = median[0][1];
        double grid_warm = median[1][0] - grid, embree_warm = median[1][1] - embree;
        fast_grid_counts counts = {0, 0, 0, 0};
        for (long k = 0; k < n; k++) {
            hit_record hit;
            fast_grid_intersect_counted(tr->g, to_ray(&chosen[k]), 0, REAL_INFINITY, &hit, &counts);
        }
        printf("    %-24s %5.1f %%  %7.1f  %7.1f  %5.2f  %7.1f  %7.1f  %5.2f  %6.2f  %6.2f  %6.2f  %6.2f\n", names[kind],
               100.0 * (double)n / (double)n_rays, 1e9 * grid / (double)n, 1e9 * embree / (double)n, embree / grid,
               1e9 * grid_warm / (double)n, 1e9 * embree_warm / (double)n, embree_warm / grid_warm,
               (double)counts.cells / (double)n, (double)counts.leaps / (double)n, (double)counts.tests / (double)n,
               (double)counts.culled / (double)n);
    }
    free(chosen);
}

int main(int argc, char **argv)
{
    const char *what = NULL;
    int size = 512, linear_rows = 32, runs = 5, knobs = 1;
    bool random_rays = false;
    triangle_test test = TRIANGLE_TEST_DEFAULT;
    fast_grid_options grid_options = fast_grid_default_options();
    for (int k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "--size") && k + 1 < argc)
            size = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--linear-rows") && k + 1 < argc)
            linear_rows = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--runs") && k + 1 < argc)
            runs = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--knobs") && k + 1 < argc)
            knobs = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--random"))
            random_rays = true;
        else if (!strcmp(argv[k], "--split") && k + 1 < argc)
            grid_options.split = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--prefetch") && k + 1 < argc) {
            const char *v = argv[++k];
            grid_options.prefetch = !strcmp(v, "auto") ? FAST_GRID_PREFETCH_AUTO
                                    : !strcmp(v, "on") ? FAST_GRID_PREFETCH_ON
                                    : !strcmp(v, "off") ? FAST_GRID_PREFETCH_OFF
                                                        : -1; /* refused by the usage check */
        }
        else if (!strcmp(argv[k], "--cramer"))
            test = TRIANGLE_CRAMER;
        else
            what = argv[k];
    }
    if (!what || size < 1 || runs < 1 || grid_options.prefetch < 0) {
        fprintf(stderr, "usage: grid_vs_embree MESH.obj|sphere:N [--size 512] [--linear-rows 32] [--runs 5] [--knobs 1|2|0] "
                        "[--random] [--cramer] [--split N] [--prefetch auto|on|off]\n");
        return 2;
    }
    float_mesh fm;
    if (!strncmp(what, "sphere:", 7))
        make_sphere(atol(what + 7), &fm);
    else
        load_obj(what, &fm);
    /* room for Embree's 16-byte loads past the last vertex */
    fm.v = realloc(fm.v, ((size_t)fm.n_v * 3 + 4) * sizeof *fm.v);

    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, test); /* the renderers' watertight test, or --cramer the lecture's */
    for (long k = 0; k < fm.n_tri; k++) {
        const unsigned *t = fm.tri + 3 * k;
        triangle tri = {mesh_vertex(&fm, t[0]), mesh_vertex(&fm, t[1]), mesh_vertex(&fm, t[2])};
        if (surface_list_add_triangle(&list, tri, 0, 0) < 0) {
            fprintf(stderr, "grid_vs_embree: out of memory\n");
            return 1;
        }
    }
    float_ray *rays = random_rays ? make_random_rays(&fm, (long)size * size) : make_rays(&fm, size);
    long n_rays = (long)size * size;
    int *prim[3];
    for (int m = 0; m < 3; m++) {
        prim[m] = malloc((size_t)n_rays * sizeof **prim);
        for (long k = 0; k < n_rays; k++)
            prim[m][k] = -2;
    }
    printf("%s: %ld triangles, %dx%d %s rays, %s, %s test, median of %d runs\n", what, fm.n_tri, size, size,
           random_rays ? "random" : "primary", REAL_NAME, test == TRIANGLE_CRAMER ? "Cramer" : "watertight", runs);

    /* Embree: a device with one build thread, its memory watched. */
    RTCDevice device = rtcNewDevice("threads=1");
    rtcSetDeviceMemoryMonitorFunction(device, monitor, NULL);
    double t0 = now();
    RTCScene scene = embree_scene(device, &fm, RTC_SCENE_FLAG_NONE);
    double embree_build = now() - t0;
    const long long default_bytes = embree_bytes, default_peak = embree_peak;
    t0 = now();
    RTCScene robust = embree_scene(device, &fm, RTC_SCENE_FLAG_ROBUST); /* its memory: what it adds */
    const double robust_build = now() - t0;
    const long long robust_bytes = embree_bytes - default_bytes;
    int *robust_prim = malloc((size_t)n_rays * sizeof *robust_prim);

    fast_grid g;
    char err[256];
    t0 = now();
    if (fast_grid_build(&g, &list, grid_options, err, sizeof err) != 0) {
        fprintf(stderr, "grid_vs_embree: %s\n", err);
        return 1;
    }
    double grid_build_time = now() - t0;

    tracer tr = {&list, &g, scene, rays, size, NULL};
    threads_bind(2); /* the 2-thread runs' team, bound as the renderers bind theirs */
    /* 1 thread by CPU time; the speed-up of 2 threads by wall-clock time, 1 against 2. */
    /* The 1-thread runs alternate grid and Embree, so that both see the same
     * load on the shared machine; medians of each. */
    double grid_runs[15], embree_runs[15], pair_ratio[15], robust_runs[15], robust_ratio[15];
    int n_runs = runs < 15 ? runs : 15;
    for (int k = 0; k < n_runs; k++) {
        tr.prim = prim[GRID];
        grid_runs[k] = trace(&tr, GRID, 1, 1, true);
        tr.prim = prim[EMBREE];
        embree_runs[k] = trace(&tr, EMBREE, 1, 1, true);
        pair_ratio[k] = embree_runs[k] / grid_runs[k]; /* one run of each, back to back */
        tr.prim = robust_prim;
        tr.scene = robust;
        robust_runs[k] = trace(&tr, EMBREE, 1, 1, true);
        tr.scene = scene;
        robust_ratio[k] = robust_runs[k] / grid_runs[k];
    }
    qsort(robust_runs, (size_t)n_runs, sizeof *robust_runs, compare_doubles);
    qsort(robust_ratio, (size_t)n_runs, sizeof *robust_ratio, compare_doubles);
    qsort(grid_runs, (size_t)n_runs, sizeof *grid_runs, compare_doubles);
    qsort(embree_runs, (size_t)n_runs, sizeof *embree_runs, compare_doubles);
    qsort(pair_ratio, (size_t)n_runs, sizeof *pair_ratio, compare_doubles);
    double grid1 = grid_runs[n_runs / 2], embree1 = embree_runs[n_runs / 2];
    tr.prim = prim[GRID];
    double grid_wall1 = best_of(&tr, GRID, 1, 1, false, runs), grid_wall2 = best_of(&tr, GRID, 1, 2, false, runs);
    tr.prim = prim[EMBREE];
    double embree_wall1 = best_of(&tr, EMBREE, 1, 1, false, runs),
           embree_wall2 = best_of(&tr, EMBREE, 1, 2, false, runs);
    const double mrays = (double)n_rays / 1e6;
    printf("  %-34s %8.3f Mrays/s  (2 threads: speed-up %.2f)\n", "grid (chapter 11)", mrays / grid1,
           grid_wall1 / grid_wall2);
    printf("  %-34s %8.3f Mrays/s  (2 threads: speed-up %.2f)\n", "Embree 3 rtcIntersect1", mrays / embree1,
           embree_wall1 / embree_wall2);
    /* The ratio of the medians, and how far the ratio moves from one pair of runs to the next (the
     * machine's load and memory move the grid's runs, which wait on memory more, more than Embree's). */
    printf("  grid / Embree: %.2f  (pair by pair, one run of each in turn: %.3f to %.3f)\n", embree1 / grid1,
           pair_ratio[0], pair_ratio[n_runs - 1]);
    const double robust1 = robust_runs[n_runs / 2];
    printf("  %-34s %8.3f Mrays/s\n", "Embree 3, RTC_SCENE_FLAG_ROBUST", mrays / robust1);
    printf("  grid / Embree robust: %.2f  (pair by pair: %.3f to %.3f)\n", robust1 / grid1, robust_ratio[0],
           robust_ratio[n_runs - 1]);
    tr.prim = prim[GRID];
    print_by_kind(&tr, prim[EMBREE], &fm, n_rays, runs);
    if (linear_rows > 0) {
        tr.prim = prim[LINEAR];
        double linear = trace(&tr, LINEAR, linear_rows, 1, true);
        long traced = (long)((size + linear_rows - 1) / linear_rows) * size;
        double rate = (double)traced / 1e6 / linear;
        printf("  %-34s %8.5f Mrays/s  (every %d-th row: %ld rays in %.2f s; the whole image would take %.0f s)\n",
               "linear scan (chapter 04)", rate, linear_rows, traced, linear, (double)n_rays / 1e6 / rate);
        printf("  grid / linear scan: %.0f\n", (mrays / grid1) / rate);
    }
    printf("  build (1 thread): grid %.3f s, Embree %.3f s\n", grid_build_time, embree_build);
    printf("  memory without the mesh: grid %.1f MB (build peak %.1f MB; %dx%dx%d cells, %ld entries), "
           "Embree %.1f MB (peak %.1f MB)\n",
           (double)fast_grid_memory(&g) / 1e6, (double)g.peak_bytes / 1e6, g.n[0], g.n[1], g.n[2], g.n_refs,
           (double)default_bytes / 1e6, (double)default_peak / 1e6);
    printf("  Embree robust: build %.3f s, memory %.1f MB\n", robust_build, (double)robust_bytes / 1e6);

    /* Agreement: the grid must match the linear scan exactly wherever both
     * ran; Embree, in float with its own test, may differ on edges. */
    long same_linear = 0, compared_linear = 0, same_embree = 0, same_robust = 0;
    for (long k = 0; k < n_rays; k++) {
        if (prim[LINEAR][k] != -2) {
            compared_linear++;
            same_linear += prim[LINEAR][k] == prim[GRID][k];
        }
        same_embree += prim[EMBREE][k] == prim[GRID][k];
        same_robust += robust_prim[k] == prim[GRID][k];
    }
    printf("  same triangle as the grid: linear scan %ld of %ld rays, Embree %ld of %ld (%.3f%%), Embree robust %ld"
           " (%.3f%%)\n",
           same_linear, compared_linear, same_embree, n_rays, 100.0 * (double)same_embree / (double)n_rays,
           same_robust, 100.0 * (double)same_robust / (double)n_rays);

    /* The knobs: density and mailboxing, 1 thread, side by side. */
    static const double densities[] = {1, 2, 4, 8, 16};
    printf("  grid knobs (1 thread): density, mailbox, leap, cull -> Mrays/s, build s, MB;"
           " per ray: cells, tests, culled\n");
    for (int variant = 0; variant < (knobs == 2 ? 1 : knobs ? 4 : 0); variant++)
        for (size_t k = 0; k < sizeof densities / sizeof densities[0]; k++) {
            fast_grid h;
            fast_grid_options opt = {.density = densities[k], .max_cells = FAST_GRID_DEFAULT_MAX_CELLS,
                                     .mailbox = variant != 1, .leap = variant != 2, .cull = variant != 3,
                                     .split = grid_options.split, .prefetch = grid_options.prefetch,
                                     .boxes = grid_options.boxes};
            t0 = now();
            if (fast_grid_build(&h, &list, opt, err, sizeof err) != 0) {
                fprintf(stderr, "grid_vs_embree: %s\n", err);
                return 1;
            }
            double build = now() - t0;
            tr.g = &h;
            tr.prim = prim[GRID];
            double t = best_of(&tr, GRID, 1, 1, true, runs);
            fast_grid_counts counts = {0, 0, 0, 0};
            for (long r = 0; r < n_rays; r += 7) {
                hit_record hit;
                fast_grid_intersect_counted(&h, to_ray(&rays[r]), 0, REAL_INFINITY, &hit, &counts);
            }
            double sampled = (double)((n_rays + 6) / 7);
            printf("    %4.1f  %-3s  %-3s  %-3s  %8.3f  %7.3f  %7.1f  %6.2f  %6.2f  %6.2f\n", densities[k],
                   opt.mailbox ? "on" : "off", opt.leap ? "on" : "off", opt.cull ? "on" : "off", mrays / t, build,
                   (double)fast_grid_memory(&h) / 1e6, (double)counts.cells / sampled, (double)counts.tests / sampled,
                   (double)counts.culled / sampled);
            fast_grid_free(&h);
        }

    rtcReleaseScene(scene);
    rtcReleaseScene(robust);
    free(robust_prim);
    rtcReleaseDevice(device);
    fast_grid_free(&g);
    surface_list_free(&list);
    for (int m = 0; m < 3; m++)
        free(prim[m]);
    free(rays);
    free(fm.v);
    free(fm.tri);
    return 0;
}
