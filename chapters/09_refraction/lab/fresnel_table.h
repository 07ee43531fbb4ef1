/* fresnel_table.h - chapter 09's lab: R against the angle, for the plot.
 *
 * For angles of incidence from 0 to 90 degrees, the reflectance of a surface
 * between air and glass of index eta, into the glass and out of it, by
 * Fresnel's equations and by Schlick's approximation, each computed as the
 * renderer computes it (refract for cos_t and the critical angle, then
 * fresnel.h).  Out of the glass it also gives Schlick's polynomial in cos_i,
 * the mistake that makes R jump at the critical angle.
 */
#ifndef CH09_FRESNEL_TABLE_H
#define CH09_FRESNEL_TABLE_H

#include <stdio.h>

#include "real.h"

/* Prints steps + 1 lines "angle_degrees in_exact in_schlick out_exact
 * out_schlick out_schlick_cos_i", after a # line naming the columns.
 * Returns 0. */
int fresnel_table(FILE *out, real eta, int steps);

#endif
