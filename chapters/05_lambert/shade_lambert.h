/* shade_lambert.h - chapter 05: the shade function of the Lambert stage.
 *
 * The lecture's "Image so far - diffuse shading": one light, no shadows,
 *
 *     Surface.shade(ray, point, normal, light)
 *         v = -normalize(ray.direction); l = normalize(light.pos - point)
 *         return L_d = k_d max(0, n . l) I / r^2
 *
 * Every shader but RGBNormals is shaded as Lambertian with its diffuseColor
 * (the Phong highlight is chapter 07's); RGBNormals keeps chapter 04's
 * (n + 1) / 2.  The scene's first light is the lecture's `light`; chapter 07
 * loops over all of them.  A scene without lights is black.
 */
#ifndef CH05_SHADE_LAMBERT_H
#define CH05_SHADE_LAMBERT_H

#include "05_lambert/tracer.h"

/* A shade_fn: the Lambert term of the first light at sp (knobs unused). */
color shade_lambert(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays);

#endif
