#include "render_loop.h"

#include <omp.h>
#include <stdio.h>
#include <time.h>
#include <unistd.h>

#include "explain.h"
#include "threads.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* splitmix64: a small, well-mixed hash of a 64-bit state. */
static uint64_t mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15u;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* A uniform number in [0, 1) from the top 24 bits, exact in float and double. */
static real unit_from(uint64_t h) { return (real)(h >> 40) * (real)(1.0 / 16777216.0); }

void render_sample_offset(unsigned long seed, int i, int j, int a, int b, int n, real *du, real *dv)
{
    if (n == 1) { /* one sample: the pixel centre, as in the lecture */
        *du = *dv = (real)0.5;
        return;
    }
    uint64_t h = mix64(mix64(mix64((uint64_t)seed) ^ (uint64_t)(uint32_t)i) ^ ((uint64_t)(uint32_t)j << 32 | (uint32_t)(a * n + b)));
    *du = ((real)a + unit_from(h)) / (real)n;
    *dv = ((real)b + unit_from(mix64(h))) / (real)n;
}

static bool is_finite(color c) { return isfinite(c.r) && isfinite(c.g) && isfinite(c.b); }

/* A pixel from its `finite` finite samples out of n2: their sum, and the sum
 * of each scaled by weight = 1/n2 (which cannot overflow). */
static color pixel_value(color sum, color scaled, int finite, int n2, real weight, nonfinite_mode mode)
{
    if (finite < n2 && mode == NONFINITE_SHOW)
        return RENDER_NONFINITE_COLOR;
    if (finite == 0)
        return color_make(0, 0, 0);
    color mean = finite == n2 ? color_scale(sum, weight) : color_scale(sum, (real)1 / (real)finite);
    if (is_finite(mean))
        return mean;
    /* The sum overflowed (samples near REAL_MAX): the scaled sum, rescaled. */
    mean = color_scale(scaled, (real)n2 / (real)finite);
    return color_make(real_fmin(mean.r, REAL_MAX), real_fmin(mean.g, REAL_MAX), real_fmin(mean.b, REAL_MAX));
}

static int side_of(int samples)
{
    int n = 1;
    while ((n + 1) * (n + 1) <= samples)
        n++;
    return n;
}

color render_pixel(sample_fn sample, const void *scene, const render_options *opt, pixel_map_fn map, int i, int j,
                   int nx, int ny, uint64_t *rays, uint64_t *nonfinite)
{
    const int n = side_of(opt->samples > 0 ? opt->samples : 1);
    const real weight = (real)1 / (real)(n * n);
    color sum = {0, 0, 0}, scaled = {0, 0, 0};
    int finite = 0;
    for (int a = 0; a < n; a++) {
        for (int b = 0; b < n; b++) {
            real du, dv;
            render_sample_offset(opt->seed, i, j, a, b, n, &du, &dv);
            real u, v;
            if (map) {
                map(i, j, nx, ny, du, dv, &u, &v);
            } else {
                u = ((real)i + du) / (real)nx;
                v = ((real)j + dv) / (real)ny;
            }
            EXPLAIN(explain_sample(a * n + b, n * n, du, dv, u, v));
            color L = sample(scene, u, v, rays);
            EXPLAIN(explain_sample_done(L));
            if (is_finite(L)) {
                sum = color_add(sum, L);
                scaled = color_add(scaled, color_scale(L, weight));
                finite++;
            }
        }
    }
    *nonfinite += (uint64_t)(n * n - finite);
    return pixel_value(sum, scaled, finite, n * n, weight, opt->nonfinite);
}

render_stats render_image(image *img, sample_fn sample, const void *scene, const render_options *opt)
{
    return render_image_mapped(img, sample, scene, opt, NULL);
}

render_stats render_image_mapped(image *img, sample_fn sample, const void *scene, const render_options *opt,
                                 pixel_map_fn map)
{
    const int nx = img->width, ny = img->height;
    const int threads = opt->threads > 0 ? opt->threads : omp_get_max_threads();
    const int show_progress = !opt->quiet && isatty(STDERR_FILENO);
    const double start = now();
    double last_report = start;
    int rows_done = 0, reported = 0;
    render_stats stats = {0};

    threads_bind(threads); /* once per process: renderer_main has done it before the scene is read */
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = 0; j < ny; j++) {
        uint64_t row_rays[RAY_KINDS] = {0};
        uint64_t row_nonfinite = 0;
        for (int i = 0; i < nx; i++)
            *image_at(img, i, j) = render_pixel(sample, scene, opt, map, i, j, nx, ny, row_rays, &row_nonfinite);
        for (int k = 0; k < RAY_KINDS; k++) {
#pragma omp atomic
            stats.by_kind[k] += row_rays[k];
        }
#pragma omp atomic
        stats.nonfinite += row_nonfinite;
        if (show_progress) {
            int done;
#pragma omp atomic capture
            done = ++rows_done;
            if (omp_get_thread_num() == 0) {
                double t = now();
                if (t - start > 1.0 && t - last_report > 0.25) {
                    last_report = t;
                    reported = 1;
                    fprintf(stderr, "\rrendering: %3d%%", (int)(100L * done / ny));
                    fflush(stderr);
                }
            }
        }
    }
    if (reported)
        fprintf(stderr, "\r                \r");
    for (int k = 0; k < RAY_KINDS; k++)
        stats.rays += stats.by_kind[k];
    stats.seconds = now() - start;
    return stats;
}

void render_summary(FILE *out, const char *name, const image *img, const render_options *opt,
                    render_stats stats, const char *output)
{
    if (opt->quiet)
        return;
    static const char *const kind_names[RAY_KINDS] = {"eye", "shadow", "reflected", "refracted"};
    int threads = opt->threads > 0 ? opt->threads : omp_get_max_threads();
    char rays[160];
    if (stats.by_kind[RAY_EYE] == stats.rays) {
        snprintf(rays, sizeof rays, "%llu rays", (unsigned long long)stats.rays);
    } else { /* "262144 eye + 101003 shadow rays" */
        size_t used = 0;
        for (int k = 0; k < RAY_KINDS && used < sizeof rays; k++)
            if (stats.by_kind[k] || k == RAY_EYE)
                used += (size_t)snprintf(rays + used, sizeof rays - used, "%s%llu %s", k ? " + " : "",
                                         (unsigned long long)stats.by_kind[k], kind_names[k]);
        if (used < sizeof rays)
            snprintf(rays + used, sizeof rays - used, " rays");
    }
    fprintf(out, "%s: %dx%d, %d spp, %s, %llu non-finite sample%s, %.3f s, %d thread%s -> %s\n", name, img->width,
            img->height, opt->samples > 0 ? opt->samples : 1, rays, (unsigned long long)stats.nonfinite,
            stats.nonfinite == 1 ? "" : "s", stats.seconds, threads, threads == 1 ? "" : "s", output);
}
