/* shade_glazed.h - chapter 08: the shade function of the mirror stage.
 *
 * The lecture's "'Glazed' material has mirror reflection and diffuse":
 *
 *     L = L_a + L_r + L_m
 *
 * with L_m "evaluated by tracing a new ray".  A shader's <mirrorCoefficient>
 * k_m (docs/scenes.md, an extension of the course's format; on a Lambertian or a
 * Phong shader) says how much of L_m the surface reflects, per colour
 * channel:
 *
 *     L = L_a + L_r + k_m L_m
 *
 * L_a + L_r is chapter 07's shading (ambient, every unblocked light, the
 * Blinn-Phong highlight), called, not copied; k_m L_m is added to it.  A
 * surface with k_m = 0 (the default) casts no mirror ray: it is shaded
 * exactly as in chapter 07.
 */
#ifndef CH08_SHADE_GLAZED_H
#define CH08_SHADE_GLAZED_H

#include "08_mirrors/path.h"

/* A shade_fn: chapter 07's L_a + L_r, plus k_m L_m where k_m is not zero
 * (tr->knobs.path: --depth and --min-weight, or their defaults). */
color shade_glazed(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays);

#endif
