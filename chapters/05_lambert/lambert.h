/* lambert.h - chapter 05: diffuse light from one point source, the lecture's "Lambertian shading"
 * (README, "Point lights"). */
#ifndef CH05_LAMBERT_H
#define CH05_LAMBERT_H

#include "color.h"
#include "scene.h"

/* The Lambert term at `point` with unit normal n (turned towards the viewer) lit by `light` (position,
 * intensity I): k_d max(0, n . l) I / r^2, with k_d = R / pi the scene's diffuseColor. */
color lambert(color k_d, vec3 point, vec3 n, const scene_light *light);

#endif
