/* fresnel.h - chapter 09: how much a glass surface reflects.
 *
 * Fresnel's R for unpolarised light (README, "How much is reflected: Fresnel"):
 *
 *     R = (r_s^2 + r_p^2) / 2,   r_s = (eta_i cos_i - eta_t cos_t) / (eta_i cos_i + eta_t cos_t),
 *                                r_p = (eta_t cos_i - eta_i cos_t) / (eta_t cos_i + eta_i cos_t)
 *
 * and Schlick's R_0 + (1 - R_0) (1 - cos)^5, R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2, with cos the
 * cosine on the side of the smaller index.  Past the critical angle R = 1 (the caller's job).
 */
#ifndef CH09_FRESNEL_H
#define CH09_FRESNEL_H

#include "real.h"

typedef enum { FRESNEL_EXACT, FRESNEL_SCHLICK } fresnel_mode;

/* The names of the modes, in enum order, NULL-terminated: the choices of --fresnel. */
extern const char *const fresnel_mode_names[];

/* Fresnel's R, cos_i and cos_t in [0, 1] (cos_t from refract), eta_i, eta_t > 0. */
real fresnel_exact(real cos_i, real cos_t, real eta_i, real eta_t);

/* Schlick's R, with the cosine on the side of the smaller index. */
real fresnel_schlick(real cos_i, real cos_t, real eta_i, real eta_t);

/* R by `mode`; 0 when eta_i == eta_t (no surface). */
real fresnel(fresnel_mode mode, real cos_i, real cos_t, real eta_i, real eta_t);

#endif
