/* lambert.h - chapter 05: diffuse light from one point source.
 *
 * The lecture's "Lambertian shading":
 *
 *     L_d = (R / pi) max(0, n . l) I / r^2
 *
 * R is the diffuse reflectance, I the intensity of the point light, r the
 * distance from the point to the light and l the unit vector towards it.  The
 * course's scene files give the diffuse coefficient k_d = R / pi directly as
 * a shader's diffuseColor (docs/scenes.md), so here L_d = k_d max(0, n . l) I / r^2,
 * per colour channel.
 */
#ifndef CH05_LAMBERT_H
#define CH05_LAMBERT_H

#include "color.h"
#include "scene.h"
#include "vec3.h"

/* The Lambert term at `point` with unit normal n (turned towards the viewer)
 * lit by `light` (position, intensity I): k_d max(0, n . l) I / r^2. */
color lambert(color k_d, vec3 point, vec3 n, const scene_light *light);

#endif
