/* path.h - chapter 08: how deep the recursion goes, and how little it may carry.
 *
 * A mirror ray is traced with trace() again, one level deeper; what it finds
 * may be a mirror too, and so on.  Two knobs stop the recursion:
 *
 *   --depth N        no ray deeper than N bounces is cast (an eye ray is depth
 *                    0, its mirror ray depth 1, ...).  A ray that would go
 *                    deeper is not traced and brings no light: black.
 *   --min-weight w   no ray is cast whose path weight, the product of the
 *                    coefficients along the path that leads to it (k_m of
 *                    each mirror, the Fresnel R or T of each glass surface of
 *                    chapter 09), is below w in every colour channel: what it
 *                    could add to the pixel is at most w times the radiance it
 *                    finds.  It brings no light either: the cut light is lost,
 *                    not estimated (a glass sphere against white shows in 212
 *                    of 512x512 pixels by at most 2/255 at the default; the
 *                    chapter's README, "The defaults, measured").
 *
 * A coefficient of zero never casts a ray, whatever the knobs (docs/design.md:
 * "no mirror rays where the mirror coefficient is zero").
 *
 * The weight travels with the tracer (tracer.weight): an eye ray's tracer
 * carries 1, and path_next hands a deeper ray a copy of the tracer that
 * carries the weight of its path.
 */
#ifndef CH08_PATH_H
#define CH08_PATH_H

#include <stdbool.h>

#include "07_blinn_phong/shade_phong.h"

/* snippet: path_knobs */
/* The knobs of chapter 08: chapter 07's, then the two that stop the
 * recursion. */
typedef struct path_knobs {
    phong_knobs phong;
    int depth;       /* --depth: the deepest bounce that is traced */
    real min_weight; /* --min-weight: the smallest path weight that is traced */
} path_knobs;
/* end snippet */

/* The defaults of --depth and --min-weight (measured in the README). */
#define PATH_DEFAULT_DEPTH 32
#define PATH_DEFAULT_MIN_WEIGHT ((real)1e-3)
/* The defaults, an initializer: chapter 07's, and the two above. */
#define PATH_KNOBS_DEFAULT \
    {.phong = PHONG_KNOBS_DEFAULT, .depth = PATH_DEFAULT_DEPTH, .min_weight = PATH_DEFAULT_MIN_WEIGHT}
/* --depth beyond this counts as this: the recursion must not exhaust the stack. */
#define PATH_MAX_DEPTH 256

/* The knobs of a tracer with chapter 08's knobs; the defaults without. */
const path_knobs *tracer_path_knobs(const tracer *tr);

/* Whether a ray leaving a point reached at `depth` with coefficient k (k_m, R
 * or T) is cast: not when depth is already the deepest, not when the path's
 * weight times k is zero or below --min-weight in every channel.  When it is,
 * *next is the tracer to trace it with, at depth + 1. */
bool path_next(const tracer *tr, int depth, color k, tracer *next);

#endif
