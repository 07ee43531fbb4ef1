/* fresnel.h - chapter 09: how much a glass surface reflects.
 *
 * The lecture's "Ideal specular reflection": the reflectance of a smooth
 * dielectric "depends on angle": a few percent head on, all of it at grazing
 * incidence.  The fraction R of unpolarised light reflected at a surface from
 * index eta_i into eta_t, with the cosines of chapter 09's refract (Fresnel's
 * equations, the average of the two polarisations):
 *
 *     r_s = (eta_i cos_i - eta_t cos_t) / (eta_i cos_i + eta_t cos_t)
 *     r_p = (eta_t cos_i - eta_i cos_t) / (eta_t cos_i + eta_i cos_t)
 *     R = (r_s^2 + r_p^2) / 2,        T = 1 - R transmitted
 *
 * Schlick's approximation replaces them by a polynomial in one cosine:
 *
 *     R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2     (R head on, either way)
 *     R = R_0 + (1 - R_0) (1 - cos)^5
 *
 * where cos is the cosine of the angle on the side of the smaller index: the
 * incoming angle on the way into glass, the transmitted one (cos_t) on the
 * way out.  With cos_i on the way out, R would jump from about 0.04 to 1 at
 * the critical angle (plotted in the README).
 *
 * Past the critical angle there is no cos_t: R = 1 (the caller's job, when
 * refract() says false).
 */
#ifndef CH09_FRESNEL_H
#define CH09_FRESNEL_H

#include "real.h"

typedef enum { FRESNEL_EXACT, FRESNEL_SCHLICK } fresnel_mode;

/* The names of the modes, in enum order, NULL-terminated: the choices of --fresnel. */
extern const char *const fresnel_mode_names[];

/* Fresnel's R for unpolarised light, cos_i and cos_t in [0, 1] (cos_t from
 * refract), indices eta_i, eta_t > 0. */
real fresnel_exact(real cos_i, real cos_t, real eta_i, real eta_t);

/* Schlick's R, with the cosine on the side of the smaller index. */
real fresnel_schlick(real cos_i, real cos_t, real eta_i, real eta_t);

/* R by `mode`; 0 when eta_i == eta_t (no surface at all: Schlick alone would
 * still give (1 - cos)^5). */
real fresnel(fresnel_mode mode, real cos_i, real cos_t, real eta_i, real eta_t);

#endif
