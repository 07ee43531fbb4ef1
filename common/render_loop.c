#include "render_loop.h"

#include <omp.h>
#include <stdio.h>
#include <time.h>
#include <unistd.h>

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

static int side_of(int samples)
{
    int n = 1;
    while ((n + 1) * (n + 1) <= samples)
        n++;
    return n;
}

render_stats render_image(image *img, sample_fn sample, const void *scene, const render_options *opt)
{
    return render_image_mapped(img, sample, scene, opt, NULL);
}

render_stats render_image_mapped(image *img, sample_fn sample, const void *scene, const render_options *opt,
                                 pixel_map_fn map)
{
    const int nx = img->width, ny = img->height;
    const int n = side_of(opt->samples > 0 ? opt->samples : 1);
    const real weight = (real)1 / (real)(n * n);
    const int threads = opt->threads > 0 ? opt->threads : omp_get_max_threads();
    const int show_progress = !opt->quiet && isatty(STDERR_FILENO);
    const double start = now();
    double last_report = start;
    int rows_done = 0, reported = 0;
    render_stats stats = {0};

#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = 0; j < ny; j++) {
        uint64_t row_rays[RAY_KINDS] = {0};
        for (int i = 0; i < nx; i++) {
            color sum = {0, 0, 0};
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
                    sum = color_add(sum, sample(scene, u, v, row_rays));
                }
            }
            *image_at(img, i, j) = color_scale(sum, weight);
        }
        for (int k = 0; k < RAY_KINDS; k++) {
#pragma omp atomic
            stats.by_kind[k] += row_rays[k];
        }
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
    fprintf(out, "%s: %dx%d, %d spp, %s, %.3f s, %d thread%s -> %s\n", name, img->width, img->height,
            opt->samples > 0 ? opt->samples : 1, rays, stats.seconds, threads, threads == 1 ? "" : "s", output);
}
