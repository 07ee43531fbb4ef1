/* shade_lambert.h - chapter 05: the Lambert stage's shade function, the lecture's
 * Surface.shade(ray, point, normal, light) (README, "The stage's shade function"). */
#ifndef CH05_SHADE_LAMBERT_H
#define CH05_SHADE_LAMBERT_H

#include "05_lambert/tracer.h"

/* A shade_fn: the Lambert term of the scene's first light with the shader's diffuseColor (black
 * without lights); RGBNormals keeps chapter 04's colour. */
color shade_lambert(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays);

#endif
