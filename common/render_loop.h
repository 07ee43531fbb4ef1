/* render_loop.h - the lecture's image-order loop, over rows in parallel.
 *
 *     for 0 <= j < n_y
 *         for 0 <= i < n_x
 *             image(i, j) = average of sample(u, v) over the pixel's samples
 *
 * With one sample per pixel, (u, v) is the pixel centre of the lecture's
 * "pixel-to-image mapping": u = (i + 0.5)/n_x, v = (j + 0.5)/n_y.  With
 * N = n^2 samples the pixel is split into n x n strata and each sample is
 * jittered inside its stratum by a hash of (seed, i, j, stratum), so every
 * pixel's value depends on nothing but its own coordinates: the image is
 * byte-identical for any number of threads.
 */
#ifndef RT_RENDER_LOOP_H
#define RT_RENDER_LOOP_H

#include <stdint.h>

#include "image.h"
#include "options.h"

/* The kinds of ray a renderer casts, counted apart in the summary line. */
typedef enum { RAY_EYE, RAY_SHADOW, RAY_REFLECTED, RAY_REFRACTED, RAY_KINDS } ray_kind;

/* Radiance seen through normalized image position (u, v) in [0,1]^2.  `rays`
 * points at RAY_KINDS counters indexed by ray_kind: a sample adds the rays it
 * cast, so `++*rays` counts one eye ray and `++rays[RAY_SHADOW]` a shadow ray. */
typedef color (*sample_fn)(const void *scene, real u, real v, uint64_t *rays);

typedef struct {
    uint64_t rays;                /* all kinds together */
    uint64_t by_kind[RAY_KINDS];  /* indexed by ray_kind */
    uint64_t nonfinite;           /* samples whose radiance had a NaN or infinite channel */
    double seconds;
} render_stats;

/* Magenta, bright enough to show at any exposure above 1e-30: the pixels of
 * non-finite samples under --nonfinite=show. */
#define RENDER_NONFINITE_COLOR color_make((real)1e30, 0, (real)1e30)

/* The pixel-to-image mapping: the normalized image position (u, v) of the
 * point (i + du, j + dv) of pixel (i, j) of an n_x x n_y image, where
 * (du, dv) in [0,1)^2 is the sample's place inside the pixel ((0.5, 0.5), the
 * centre, for one sample).  Chapter 01 implements it (pixel_to_image). */
typedef void (*pixel_map_fn)(int i, int j, int nx, int ny, real du, real dv, real *u, real *v);

/* Pixel (i, j) of an nx x ny image, as render_image_mapped computes it: the
 * mean of its samples (opt->samples, opt->seed, opt->nonfinite), each mapped
 * by `map`; adds the rays cast to rays[] and the non-finite samples to
 * *nonfinite.  --explain (explain.h) calls it for the pixel it explains. */
color render_pixel(sample_fn sample, const void *scene, const render_options *opt, pixel_map_fn map, int i, int j,
                   int nx, int ny, uint64_t *rays, uint64_t *nonfinite);

/* render_image with the mapping `map`; NULL maps as pixel_to_image does,
 * for the suites of common/, which link no chapter. */
render_stats render_image_mapped(image *img, sample_fn sample, const void *scene, const render_options *opt,
                                 pixel_map_fn map);

/* Fills img (already sized) using opt->samples (0 counts as 1), opt->threads
 * and opt->seed.  Shows a progress line on stderr when stderr is a terminal,
 * the render takes more than about a second, and opt->quiet is false.
 *
 * No NaN or infinity reaches a pixel.  A sample with a non-finite channel is
 * counted in stats.nonfinite and, by opt->nonfinite, left out of its pixel's
 * mean (the mean of the pixel's finite samples; black when it has none) or,
 * under NONFINITE_SHOW, its pixel is painted RENDER_NONFINITE_COLOR.  Finite
 * samples whose sum overflows are averaged with each scaled first. */
render_stats render_image(image *img, sample_fn sample, const void *scene, const render_options *opt);

/* The one-line summary:
 *     "<name>: 512x512, 1 spp, 262144 rays, 0 non-finite samples, 0.050 s, 2 threads -> out.png".
 * When secondary rays were cast, the count is split: "262144 eye + 101003 shadow rays".  The count of
 * non-finite samples is always there, 0 included, so that a reader knows it was counted. */
void render_summary(FILE *out, const char *name, const image *img, const render_options *opt,
                    render_stats stats, const char *output);

/* The sample position inside a pixel: stratum (a, b) of n x n, jittered. */
void render_sample_offset(unsigned long seed, int i, int j, int a, int b, int n, real *du, real *dv);

#endif
