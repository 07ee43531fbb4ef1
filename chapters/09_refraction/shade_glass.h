/* shade_glass.h - chapter 09: the shade function of the refraction stage.
 *
 * A Glass shader (<refractiveIndex> eta, 1.5 by default) reflects and
 * transmits, nothing else (README, "The glass shader"):
 *
 *     L = R L_reflected + (1 - R) L_transmitted
 *
 * The geometric normal, pointing out of the glass, decides entering or leaving
 * ("Entering and leaving"); every other shader is chapter 08's shade_glazed.
 */
#ifndef CH09_SHADE_GLASS_H
#define CH09_SHADE_GLASS_H

#include "08_mirrors/path.h"
#include "09_refraction/fresnel.h"

/* snippet: glass_knobs */
/* The knobs of chapter 09: chapter 08's, then --fresnel. */
typedef struct glass_knobs {
    path_knobs path;
    int fresnel; /* a fresnel_mode: --fresnel */
} glass_knobs;
/* end snippet */

/* The defaults, an initializer: chapter 08's, and Fresnel's exact equations. */
#define GLASS_KNOBS_DEFAULT {.path = PATH_KNOBS_DEFAULT, .fresnel = FRESNEL_EXACT}

/* The Fresnel mode of a tracer with chapter 09's knobs; exact without. */
fresnel_mode tracer_fresnel(const tracer *tr);

/* What happens to the ray at a glass point: the indices on its two sides,
 * whether it is transmitted and where, and Fresnel's R (1 when it is not). */
typedef struct {
    real eta_i, eta_t; /* the incoming side's index and the far side's */
    real cos_i;        /* cos(theta_i) = v . n */
    bool transmits;    /* false past the critical angle */
    vec3 T;            /* the unit transmitted direction, when it transmits */
    real cos_t;        /* cos(theta_t), when it transmits */
    real R;            /* the reflected fraction; 1 - R is transmitted */
} glass_event;

/* The event at sp, a point of a glass surface of index eta, with `mode`. */
glass_event glass_at(const shading_point *sp, real eta, fresnel_mode mode);

/* L_transmitted: the radiance traced along direction T from sp's point, into
 * the far side, one level deeper than `depth`, counted as RAY_REFRACTED;
 * black when path_next stops the path with coefficient k. */
color transmitted_radiance(const tracer *tr, const shading_point *sp, vec3 T, color k, int depth, uint64_t *rays);

/* A shade_fn: R L_reflected + (1 - R) L_transmitted on a Glass shader,
 * chapter 08's shade_glazed on any other. */
color shade_glass(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays);

#endif
