/* refract.h - chapter 09: the transmitted direction, and total internal reflection.
 *
 * The lecture's "Reflected and transmitted rays": for an incoming ray
 * p + t d, split the unit direction d at the surface into a cosine part
 * C_i, along the unit normal n on the incoming side (d . n <= 0), and a sine
 * part S_i, along the surface:
 *
 *     cos(theta_i) = -(d . n)        C_i = cos(theta_i) n        S_i = d + C_i
 *
 * so that |C_i| = cos(theta_i), |S_i| = sin(theta_i), and the reflected
 * direction is R = C_i + S_i.  Snell's law, eta_i sin(theta_i) = eta_t
 * sin(theta_t), scales the sine part, and the cosine part is what is left of
 * a unit vector, on the far side:
 *
 *     S_t = (eta_i / eta_t) S_i      cos(theta_t) = sqrt(1 - |S_t|^2)
 *     C_t = -cos(theta_t) n          T = C_t + S_t
 *
 * computed, with r = eta_i / eta_t, from the cosine rather than from the
 * vector S_t, and grouped by d and n, so that r = 1 gives T = d exactly:
 *
 *     cos^2(theta_t) = (1 - r^2) + r^2 cos^2(theta_i)
 *     T = r d + (r cos(theta_i) - cos(theta_t)) n
 *
 * When |S_t|^2 > 1 (cos^2(theta_t) < 0) there is no such direction: past the critical angle
 * theta_c = asin(eta_t / eta_i), possible only on the way out of the denser
 * medium (eta_i > eta_t), no light is transmitted and all of it is reflected
 * ("total internal reflection").  At theta_c itself, |S_t| = 1 and T runs
 * along the surface.
 */
#ifndef CH09_REFRACT_H
#define CH09_REFRACT_H

#include <stdbool.h>

#include "vec3.h"

/* The transmitted direction of the unit direction d through a surface with
 * unit normal n on d's side (d . n <= 0), from index eta_i into eta_t: true
 * with the unit direction in *T and cos(theta_t) >= 0 in *cos_t, or false
 * (total internal reflection; *T and *cos_t untouched). */
bool refract(vec3 d, vec3 n, real eta_i, real eta_t, vec3 *T, real *cos_t);

#endif
