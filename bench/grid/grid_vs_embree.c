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
 * (from wall-clock time), the build times
 * and the memory of the grid and of Embree's BVH (both without the mesh
 * itself), the grid's knobs side by side, and how often the three agree on
 * the triangle hit.  The grid answers as rtcIntersect1 does, with the hit
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
#include "mesh.h"
#include "threads.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- the scene: float vertices and triangles ---------------------------------------- */

typedef struct {
    float *v; /* 3 per vertex */
    unsigned *tri; /* 3 per triangle */
    long n_v, n_tri;
} float_mesh;

static void load_obj(const char *path, float_mesh *fm)
{
    mesh m;
    char err[512];
    if (mesh_load(path, &m, err, sizeof err) != 0) {
        fprintf(stderr, "grid_vs_embree: %s\n", err);
        exit(1);
    }
    fm->n_v = m.n_positions;
    fm->n_tri = m.n_faces;
    fm->v = malloc((size_t)fm->n_v * 3 * sizeof *fm->v);
    fm->tri = malloc((size_t)fm->n_tri * 3 * sizeof *fm->tri);
    for (long k = 0; k < fm->n_v; k++) {
        fm->v[3 * k] = (float)m.positions[k].x;
        fm->v[3 * k + 1] = (float)m.positions[k].y;
        fm->v[3 * k + 2] = (float)m.positions[k].z;
    }
    for (long k = 0; k < fm->n_tri; k++)
        for (int j = 0; j < 3; j++)
            fm->tri[3 * k + j] = (unsigned)m.faces[k].v[j];
    mesh_free(&m);
}

/* A unit sphere of nu x nv quads in longitude and latitude: the pole rows
 * give one triangle per quad, the others two: 2 nu (nv - 1) triangles. */
static void make_sphere(long wanted, float_mesh *fm)
{
    long nu = (long)sqrt((double)wanted), nv = wanted / (2 * nu) + 1;
    fm->n_v = nu * (nv + 1);
    fm->v = malloc((size_t)fm->n_v * 3 * sizeof *fm->v);
    fm->tri = malloc((size_t)(2 * nu * nv) * 3 * sizeof *fm->tri);
    const double pi = 3.14159265358979323846;
    for (long j = 0; j <= nv; j++)
        for (long i = 0; i < nu; i++) {
            double theta = pi * (double)j / (double)nv, phi = 2 * pi * (double)i / (double)nu;
            float *p = fm->v + 3 * (j * nu + i);
            p[0] = (float)(sin(theta) * cos(phi));
            p[1] = (float)cos(theta);
            p[2] = (float)(sin(theta) * sin(phi));
        }
    fm->n_tri = 0;
    for (long j = 0; j < nv; j++)
        for (long i = 0; i < nu; i++) {
            unsigned a = (unsigned)(j * nu + i), b = (unsigned)(j * nu + (i + 1) % nu);
            unsigned c = a + (unsigned)nu, d = b + (unsigned)nu;
            if (j != nv - 1) { /* not at the south pole, where c and d coincide */
                unsigned *t = fm->tri + 3 * fm->n_tri++;
                t[0] = a, t[1] = c, t[2] = d;
            }
            if (j != 0) { /* not at the north pole, where a and b coincide */
                unsigned *t = fm->tri + 3 * fm->n_tri++;
                t[0] = a, t[1] = d, t[2] = b;
            }
        }
}

static vec3 vertex(const float_mesh *fm, unsigned k)
{
    return vec3_make(fm->v[3 * k], fm->v[3 * k + 1], fm->v[3 * k + 2]);
}

/* ---- the rays ------------------------------------------------------------------------ */

typedef struct {
    float o[3], d[3];
} float_ray;

/* The bounding box of the mesh's vertices. */
static void mesh_box(const float_mesh *fm, float lo[3], float hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = INFINITY;
        hi[a] = -INFINITY;
    }
    for (long k = 0; k < fm->n_v; k++)
        for (int a = 0; a < 3; a++) {
            lo[a] = fminf(lo[a], fm->v[3 * k + a]);
            hi[a] = fmaxf(hi[a], fm->v[3 * k + a]);
        }
}

/* A pinhole camera looking at the mesh's box from the front and a little
 * above, its view filled by the mesh; directions rounded to float. */
static float_ray *make_rays(const float_mesh *fm, int size)
{
    float lo[3], hi[3];
    mesh_box(fm, lo, hi);
    double c[3], radius = 0;
    for (int a = 0; a < 3; a++) {
        c[a] = 0.5 * ((double)lo[a] + hi[a]);
        radius += 0.25 * ((double)hi[a] - lo[a]) * ((double)hi[a] - lo[a]);
    }
    radius = sqrt(radius);
    const double dir[3] = {0.25, 0.3, 1}, len = sqrt(0.25 * 0.25 + 0.3 * 0.3 + 1);
    double eye[3], w[3];
    for (int a = 0; a < 3; a++) {
        eye[a] = c[a] + 3 * radius * dir[a] / len;
        w[a] = -dir[a] / len;
    }
    /* right = w x up (up = +y), up' = right x w */
    double right[3] = {-w[2], 0, w[0]}, rl = sqrt(right[0] * right[0] + right[2] * right[2]);
    for (int a = 0; a < 3; a++)
        right[a] /= rl;
    double up[3] = {right[1] * w[2] - right[2] * w[1], right[2] * w[0] - right[0] * w[2],
                    right[0] * w[1] - right[1] * w[0]};
    const double s = 0.8 * radius / (3 * radius); /* the half-width of the view at distance 1 */
    float_ray *rays = malloc((size_t)size * size * sizeof *rays);
    for (int j = 0; j < size; j++)
        for (int i = 0; i < size; i++) {
            double u = 2 * (i + 0.5) / size - 1, v = 1 - 2 * (j + 0.5) / size;
            float_ray *r = &rays[(long)j * size + i];
            for (int a = 0; a < 3; a++) {
                r->o[a] = (float)eye[a];
                r->d[a] = (float)(w[a] + s * (u * right[a] + v * up[a]));
            }
        }
    return rays;
}

/* Incoherent rays: origins uniform in the mesh's box (many of them inside
 * the mesh, as the origins of shadow and reflected rays are), directions
 * uniform on the sphere; a fixed generator, so every run gets the same rays. */
static float_ray *make_random_rays(const float_mesh *fm, long n)
{
    float lo[3], hi[3];
    mesh_box(fm, lo, hi);
    uint64_t state = 0x9E3779B97F4A7C15ull;
    float_ray *rays = malloc((size_t)n * sizeof *rays);
    for (long k = 0; k < n; k++) {
        double u[5];
        for (int q = 0; q < 5; q++) { /* xorshift64*, the top 53 bits */
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            u[q] = (double)((state * 0x2545F4914F6CDD1Dull) >> 11) * 0x1p-53;
        }
        double z = 2 * u[3] - 1, phi = 6.283185307179586 * u[4], s = sqrt(1 - z * z);
        const double dir[3] = {s * cos(phi), s * sin(phi), z};
        for (int a = 0; a < 3; a++) {
            rays[k].o[a] = (float)(lo[a] + u[a] * ((double)hi[a] - lo[a]));
            rays[k].d[a] = (float)dir[a];
        }
    }
    return rays;
}

static ray to_ray(const float_ray *r) { return (ray){{r->o[0], r->o[1], r->o[2]}, {r->d[0], r->d[1], r->d[2]}}; }

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

static RTCScene embree_scene(RTCDevice device, const float_mesh *fm)
{
    RTCScene scene = rtcNewScene(device);
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
            const float_ray *fr = &tr->rays[k];
            if (method == EMBREE) {
                struct RTCRayHit rh;
                memset(&rh, 0, sizeof rh);
                rh.ray.org_x = fr->o[0], rh.ray.org_y = fr->o[1], rh.ray.org_z = fr->o[2];
                rh.ray.dir_x = fr->d[0], rh.ray.dir_y = fr->d[1], rh.ray.dir_z = fr->d[2];
                rh.ray.tnear = 0;
                rh.ray.tfar = INFINITY;
                rh.ray.mask = (unsigned)-1;
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(tr->scene, &context, &rh);
                tr->prim[k] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : (int)rh.hit.primID;
            } else {
                if (method == GRID) {
                    fast_grid_hit hit;
                    tr->prim[k] = fast_grid_closest(tr->g, to_ray(fr), 0, REAL_INFINITY, &hit) ? hit.surface : -1;
                } else {
                    hit_record hit;
                    tr->prim[k] = surfaces_intersect(tr->list, to_ray(fr), 0, REAL_INFINITY, &hit) ? hit.surface : -1;
                }
            }
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
        triangle tri = {vertex(&fm, t[0]), vertex(&fm, t[1]), vertex(&fm, t[2])};
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
    RTCScene scene = embree_scene(device, &fm);
    double embree_build = now() - t0;

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
    double grid_runs[15], embree_runs[15];
    int n_runs = runs < 15 ? runs : 15;
    for (int k = 0; k < n_runs; k++) {
        tr.prim = prim[GRID];
        grid_runs[k] = trace(&tr, GRID, 1, 1, true);
        tr.prim = prim[EMBREE];
        embree_runs[k] = trace(&tr, EMBREE, 1, 1, true);
    }
    qsort(grid_runs, (size_t)n_runs, sizeof *grid_runs, compare_doubles);
    qsort(embree_runs, (size_t)n_runs, sizeof *embree_runs, compare_doubles);
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
    printf("  grid / Embree: %.2f\n", embree1 / grid1);
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
           (double)embree_bytes / 1e6, (double)embree_peak / 1e6);

    /* Agreement: the grid must match the linear scan exactly wherever both
     * ran; Embree, in float with its own test, may differ on edges. */
    long same_linear = 0, compared_linear = 0, same_embree = 0;
    for (long k = 0; k < n_rays; k++) {
        if (prim[LINEAR][k] != -2) {
            compared_linear++;
            same_linear += prim[LINEAR][k] == prim[GRID][k];
        }
        same_embree += prim[EMBREE][k] == prim[GRID][k];
    }
    printf("  same triangle as the grid: linear scan %ld of %ld rays, Embree %ld of %ld (%.3f%%)\n", same_linear,
           compared_linear, same_embree, n_rays, 100.0 * (double)same_embree / (double)n_rays);

    /* The knobs: density and mailboxing, 1 thread, side by side. */
    static const double densities[] = {1, 2, 4, 8, 16};
    printf("  grid knobs (1 thread): density, mailbox, leap, cull -> Mrays/s, build s, MB;"
           " per ray: cells, tests, culled\n");
    for (int variant = 0; variant < (knobs == 2 ? 1 : knobs ? 4 : 0); variant++)
        for (size_t k = 0; k < sizeof densities / sizeof densities[0]; k++) {
            fast_grid h;
            fast_grid_options opt = {.density = densities[k], .max_cells = FAST_GRID_DEFAULT_MAX_CELLS,
                                     .mailbox = variant != 1, .leap = variant != 2, .cull = variant != 3,
                                     .split = grid_options.split, .prefetch = grid_options.prefetch};
            t0 = now();
            if (fast_grid_build(&h, &list, opt, err, sizeof err) != 0) {
                fprintf(stderr, "grid_vs_embree: %s\n", err);
                return 1;
            }
            double build = now() - t0;
            tr.g = &h;
            tr.prim = prim[GRID];
            double t = best_of(&tr, GRID, 1, 1, true, runs);
            fast_grid_counts counts = {0, 0, 0};
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
