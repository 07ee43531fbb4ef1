/* The render loop (common/render_loop.h): pixel centres, samples, threads. */
#ifdef __linux__
#define _GNU_SOURCE /* sched_getaffinity, cpu_set_t */
#include <sched.h>
#endif

#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "render_loop.h"
#include "suite.h"
#include "threads.h"

/* A "scene" that returns the sample position as a colour. */
static color position(const void *scene, real u, real v, uint64_t *rays)
{
    (void)scene;
    ++*rays;
    return color_make(u, v, 0);
}

/* A pattern with no structure a wrong pixel could hide in; it "casts" one
 * eye ray, and a shadow ray on the pixels left of the diagonal. */
static color pattern(const void *scene, real u, real v, uint64_t *rays)
{
    (void)scene;
    ++*rays;
    rays[RAY_SHADOW] += u < v;
    return color_make(real_sqrt(u * 7 + v), u * v, (real)(u > v));
}

static void test_one_sample_is_the_pixel_centre(void **state)
{
    (void)state;
    image img;
    assert_int_equal(0, image_init(&img, 4, 2));
    render_options opt = {.samples = 1, .threads = 1, .quiet = true};
    render_stats stats = render_image(&img, position, NULL, &opt);
    assert_int_equal(8, stats.rays);
    for (int j = 0; j < 2; j++) {
        for (int i = 0; i < 4; i++) {
            /* u = (i + 0.5)/n_x, v = (j + 0.5)/n_y: exact in binary for n = 4, 2 */
            assert_close((i + 0.5) / 4, image_at(&img, i, j)->r, 0);
            assert_close((j + 0.5) / 2, image_at(&img, i, j)->g, 0);
        }
    }
    image_free(&img);
}

static void test_stratified_samples_stay_in_their_strata(void **state)
{
    (void)state;
    for (int i = 0; i < 5; i++) {
        for (int a = 0; a < 3; a++) {
            for (int b = 0; b < 3; b++) {
                real du, dv;
                render_sample_offset(7, i, 2 * i, a, b, 3, &du, &dv);
                assert_true(du >= (real)a / 3 && du < (real)(a + 1) / 3);
                assert_true(dv >= (real)b / 3 && dv < (real)(b + 1) / 3);
            }
        }
    }
    real du, dv;
    render_sample_offset(7, 1, 1, 0, 0, 1, &du, &dv); /* one sample: the centre */
    assert_close(0.5, du, 0);
    assert_close(0.5, dv, 0);
}

static void test_samples_average_to_the_pixel_mean(void **state)
{
    (void)state;
    /* u is linear, so the mean of 16 jittered samples over one pixel is its
     * centre within the jitter's spread: 1/(2*4) of a pixel per stratum,
     * averaged over 4 independent columns: well inside 1/8 pixel. */
    image img;
    assert_int_equal(0, image_init(&img, 1, 1));
    render_options opt = {.samples = 16, .threads = 1, .quiet = true};
    render_stats stats = render_image(&img, position, NULL, &opt);
    assert_int_equal(16, stats.rays);
    assert_close(0.5, image_at(&img, 0, 0)->r, 1.0 / 8);
    assert_close(0.5, image_at(&img, 0, 0)->g, 1.0 / 8);
    image_free(&img);
}

static void test_any_thread_count_gives_the_same_image(void **state)
{
    (void)state;
    image one, two, seeded;
    assert_int_equal(0, image_init(&one, 37, 23));
    assert_int_equal(0, image_init(&two, 37, 23));
    assert_int_equal(0, image_init(&seeded, 37, 23));
    render_options opt = {.samples = 4, .threads = 1, .seed = 3, .quiet = true};
    render_stats s1 = render_image(&one, pattern, NULL, &opt);
    opt.threads = 2;
    render_stats s2 = render_image(&two, pattern, NULL, &opt);
    assert_int_equal(37 * 23 * 4, s1.by_kind[RAY_EYE]);
    assert_true(s1.by_kind[RAY_SHADOW] > 0 && s1.by_kind[RAY_SHADOW] < 37 * 23 * 4);
    assert_int_equal(0, s1.by_kind[RAY_REFLECTED] + s1.by_kind[RAY_REFRACTED]);
    assert_int_equal(s1.by_kind[RAY_EYE] + s1.by_kind[RAY_SHADOW], s1.rays);
    assert_memory_equal(s1.by_kind, s2.by_kind, sizeof s1.by_kind);
    assert_memory_equal(one.pixels, two.pixels, sizeof(color) * 37 * 23);
    opt.seed = 4; /* another seed moves the samples */
    render_image(&seeded, pattern, NULL, &opt);
    assert_memory_not_equal(one.pixels, seeded.pixels, sizeof(color) * 37 * 23);
    image_free(&one);
    image_free(&two);
    image_free(&seeded);
}

/* A mapping that records what it is given: (u, v) = (i + du, 10 (j + dv))
 * in pixel units, so that the test can read back i, j, du, dv. */
static void record_map(int i, int j, int nx, int ny, real du, real dv, real *u, real *v)
{
    (void)nx;
    (void)ny;
    *u = (real)i + du;
    *v = 10 * ((real)j + dv);
}

/* render_image_mapped asks the renderer's mapping (chapter 01's
 * pixel_to_image) for every sample, with the pixel, the image size and the
 * sample's place; NULL maps to the pixel centres like pixel_to_image. */
static void test_the_mapping_is_the_renderers(void **state)
{
    (void)state;
    image img;
    assert_int_equal(0, image_init(&img, 3, 2));
    render_options opt = {.samples = 1, .threads = 1, .quiet = true};
    render_image_mapped(&img, position, NULL, &opt, record_map);
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 3; i++) {
            assert_close(i + 0.5, image_at(&img, i, j)->r, 0);
            assert_close(10 * (j + 0.5), image_at(&img, i, j)->g, 0);
        }
    render_image_mapped(&img, position, NULL, &opt, NULL);
    assert_close(2.5 / 3, image_at(&img, 2, 1)->r, 2 * REAL_EPSILON);
    assert_close(1.5 / 2, image_at(&img, 2, 1)->g, 0);
    image_free(&img);
}

/* The summary line names the kinds of ray apart once there are secondary rays. */
static void test_summary_counts_ray_kinds_apart(void **state)
{
    (void)state;
    image img = {.width = 4, .height = 2};
    render_options opt = {.samples = 1, .threads = 2};
    char line[256];
    FILE *out = fmemopen(line, sizeof line, "w");
    assert_non_null(out);
    render_stats eye_only = {.rays = 8, .by_kind = {8, 0, 0, 0}, .seconds = 0.5};
    render_summary(out, "x", &img, &opt, eye_only, "x.png");
    fflush(out);
    assert_string_equal("x: 4x2, 1 spp, 8 rays, 0 non-finite samples, 0.500 s, 2 threads -> x.png\n", line);
    rewind(out);
    render_stats mixed = {.rays = 19, .by_kind = {8, 6, 0, 5}, .nonfinite = 1, .seconds = 0.25};
    render_summary(out, "x", &img, &opt, mixed, "x.png");
    fputc('\0', out);
    fclose(out);
    assert_string_equal(
        "x: 4x2, 1 spp, 8 eye + 6 shadow + 5 refracted rays, 1 non-finite sample, 0.250 s, 2 threads -> x.png\n",
        line);
}

/* Column 0 of each pixel's strata is NaN on the left half of the image and
 * infinite on the right; column 1 is finite, 0.25 + u.  Pixel (0, 0) of a
 * 2x1 image is all NaN. */
static color poisoned(const void *scene, real u, real v, uint64_t *rays)
{
    (void)scene;
    (void)v;
    ++*rays;
    real frac = u * 4 - real_floor(u * 4); /* where in its pixel of a 4-wide image the sample is */
    if (frac < (real)0.5)
        return u < (real)0.5 ? color_make(NAN, 1, 1) : color_make(1, INFINITY, 1);
    return color_make((real)0.25 + u, (real)0.25 + u, (real)0.25 + u);
}

static color all_nan(const void *scene, real u, real v, uint64_t *rays)
{
    (void)scene;
    (void)u;
    (void)v;
    ++*rays;
    return color_make(NAN, NAN, NAN);
}

/* Near REAL_MAX: four finite samples whose sum overflows. */
static color huge(const void *scene, real u, real v, uint64_t *rays)
{
    (void)scene;
    (void)u;
    (void)v;
    ++*rays;
    return color_make(REAL_MAX / 2, REAL_MAX, 1);
}

static bool finite_pixel(color c) { return isfinite(c.r) && isfinite(c.g) && isfinite(c.b); }

/* Non-finite samples are counted, never reach a pixel, and are dropped or
 * shown as the knob says. */
static void test_nonfinite_samples_are_counted_and_kept_out(void **state)
{
    (void)state;
    image img, shown;
    assert_int_equal(0, image_init(&img, 4, 3));
    assert_int_equal(0, image_init(&shown, 4, 3));
    /* 4 spp: strata a = 0 (u offset below 0.5) are poisoned, a = 1 finite */
    render_options opt = {.samples = 4, .threads = 2, .seed = 9, .quiet = true};
    render_stats stats = render_image(&img, poisoned, NULL, &opt);
    assert_int_equal(4 * 3 * 2, stats.nonfinite); /* two of each pixel's four samples */
    assert_int_equal(4 * 3 * 4, stats.rays);
    for (int j = 0; j < 3; j++) {
        for (int i = 0; i < 4; i++) {
            color c = *image_at(&img, i, j);
            assert_true(finite_pixel(c));
            /* the mean of the two finite samples, each 0.25 + u with u in the
             * right half of pixel i: between 0.25 + (i + 0.5)/4 and 0.25 + (i + 1)/4 */
            assert_true(c.r >= (real)0.25 + ((real)i + (real)0.5) / 4 && c.r <= (real)0.25 + ((real)i + 1) / 4);
        }
    }
    opt.nonfinite = NONFINITE_SHOW;
    stats = render_image(&shown, poisoned, NULL, &opt);
    assert_int_equal(4 * 3 * 2, stats.nonfinite);
    color magenta = RENDER_NONFINITE_COLOR;
    assert_memory_equal(&magenta, image_at(&shown, 2, 1), sizeof magenta);
    image_free(&img);
    image_free(&shown);

    /* no finite sample at all: black, not NaN */
    assert_int_equal(0, image_init(&img, 2, 1));
    opt.nonfinite = NONFINITE_DROP;
    stats = render_image(&img, all_nan, NULL, &opt);
    assert_int_equal(2 * 4, stats.nonfinite);
    assert_close(0, image_at(&img, 0, 0)->r, 0);
    assert_close(0, image_at(&img, 1, 0)->b, 0);
    /* finite samples whose sum overflows: their mean, exactly (halving and
     * the scale by 4 then 1/4 are exact in binary) */
    stats = render_image(&img, huge, NULL, &opt);
    assert_int_equal(0, stats.nonfinite);
    assert_true(finite_pixel(*image_at(&img, 1, 0)));
    assert_close(REAL_MAX / 2, image_at(&img, 1, 0)->r, 0);
    assert_close(REAL_MAX, image_at(&img, 1, 0)->g, 0);
    assert_close(1, image_at(&img, 1, 0)->b, REAL_EPSILON);
    image_free(&img);
}

/* threads_bind: after it, each thread of a team of that size may run on
 * one processor only, and no two on the same one.  Skipped where it binds
 * nothing by design: off Linux, with fewer than two processors, or when the
 * environment chooses the binding. */
static void test_each_thread_is_bound_to_a_processor_of_its_own(void **state)
{
    (void)state;
#ifdef __linux__
    cpu_set_t allowed;
    assert_int_equal(0, sched_getaffinity(0, sizeof allowed, &allowed));
    if (CPU_COUNT(&allowed) < 2 || getenv("OMP_PROC_BIND") || getenv("OMP_PLACES"))
        skip();
    threads_bind(2);
    int count[2] = {0, 0}, cpu[2] = {-1, -1};
#pragma omp parallel num_threads(2)
    {
        const int k = omp_get_thread_num();
        cpu_set_t mine;
        if (sched_getaffinity(0, sizeof mine, &mine) == 0) {
            count[k] = CPU_COUNT(&mine);
            for (int c = 0; c < CPU_SETSIZE; c++)
                if (CPU_ISSET(c, &mine))
                    cpu[k] = c;
        }
    }
    assert_int_equal(1, count[0]);
    assert_int_equal(1, count[1]);
    assert_true(cpu[0] != cpu[1]);
    assert_true(CPU_ISSET(cpu[0], &allowed) && CPU_ISSET(cpu[1], &allowed));
#else
    skip();
#endif
}

static const graded_test tests[] = {
    /* first: the others' renders bind the process's threads, and this one
     * reads the processors the process may run on before any binding */
    GRADED(test_each_thread_is_bound_to_a_processor_of_its_own, 0),
    GRADED(test_one_sample_is_the_pixel_centre, 0),
    GRADED(test_stratified_samples_stay_in_their_strata, 0),
    GRADED(test_samples_average_to_the_pixel_mean, 0),
    GRADED(test_any_thread_count_gives_the_same_image, 0),
    GRADED(test_the_mapping_is_the_renderers, 0),
    GRADED(test_summary_counts_ray_kinds_apart, 0),
    GRADED(test_nonfinite_samples_are_counted_and_kept_out, 0),
};
SUITE_MAIN("common_render", tests)
