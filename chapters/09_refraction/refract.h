/* refract.h - chapter 09: the transmitted direction, and total internal reflection.
 *
 * The lecture's T = C_t + S_t, with r = eta_i / eta_t and cos_i = -(d . n),
 * regrouped as the README derives it ("The transmitted direction"):
 *
 *     cos^2(theta_t) = (1 - r^2) + r^2 cos_i^2      T = r d + (r cos_i - cos(theta_t)) n
 */
#ifndef CH09_REFRACT_H
#define CH09_REFRACT_H

#include <stdbool.h>

#include "vec3.h"

/* The transmitted direction of the unit direction d through a surface with
 * unit normal n on d's side (d . n <= 0), from index eta_i into eta_t: true
 * with the unit direction in *T and cos(theta_t) >= 0 in *cos_t, or false
 * past the critical angle (cos^2(theta_t) < 0: total internal reflection;
 * *T and *cos_t untouched). */
bool refract(vec3 d, vec3 n, real eta_i, real eta_t, vec3 *T, real *cos_t);

#endif
