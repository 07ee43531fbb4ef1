/* shade_glass.h - chapter 09: the shade function of the refraction stage.
 *
 * The lecture's "Recursive Shading Model" with both of its recursive terms:
 * a Glass shader (docs/scenes.md: <shader type="Glass"> with <refractiveIndex>
 * eta, 1.5 by default) reflects and transmits, and nothing else:
 *
 *     L = R L_reflected + (1 - R) L_transmitted
 *
 * L_reflected is traced along the mirror direction (chapter 08's
 * mirror_radiance, with k_m = R), L_transmitted along Snell's transmitted
 * direction T (refract.h), and R is Fresnel's reflectance (fresnel.h, exact
 * or Schlick by --fresnel).  Past the critical angle R = 1 and no
 * transmitted ray is cast.
 *
 * Entering or leaving is decided by the sign of d . n with n the GEOMETRIC
 * normal, which points out of the glass: d . n < 0, the ray comes from
 * outside (air, eta_i = 1, eta_t = eta); otherwise it is leaving, the normal
 * is flipped and the indices swapped (eta_i = eta, eta_t = 1).  The
 * directions are computed about the shading normal sp->n, which is turned
 * towards the incoming ray already (the flipped normal on the way out).  A
 * glass object must be closed, its normals pointing out (a sphere, a box, a
 * mesh wound counter-clockwise seen from outside), and no two glass objects
 * may touch: the renderer knows air and glass, not glass next to water.
 *
 * Nothing is absorbed inside: a path through glass loses only what is
 * reflected away at its surfaces, however long it runs inside.  Glass blocks
 * the shadow rays of chapter 06 like any surface (the light it focuses on the
 * floor is a caustic, which rays traced from the eye do not find).  Every
 * other shader is shaded by chapter 08 (shade_glazed).
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

/* The option rows of chapters 06-09's knobs, and the tracer's knobs, aimed
 * at *k; returns how many rows. */
int glass_knob_rows(glass_knobs *k, knob *rows, stage_knobs *aimed);

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
