/* glass_limits.h - chapter 09's lab: where the build's precision gives out.
 *
 * The chapter's checks, pushed to grazing angles and to scales far from the
 * unit sphere at the origin, each computed as the renderer computes it
 * (refract, fresnel, glass_at, chapter 04's closest hit, chapter 06's
 * spawn_ray):
 *   - equal indices: |T - d| at angles of incidence up to 89.999 degrees;
 *   - the critical angle: how far from theta_c the build still decides
 *     wrongly between transmission and total internal reflection;
 *   - R + T = 1: the largest |R + T - 1| (T from the transmission amplitudes);
 *   - a ray through the centre of a glass sphere of radius s at
 *     s (3.7, 2.9, -4.3): the angle between the ray that leaves and the one
 *     that came, and the distance of the leaving ray from the centre, over s;
 *   - a slab of thickness s with parallel faces: the angle between the ray
 *     that leaves and the one that came, at angles up to 89.9 degrees.
 * `lab --limits` prints them for the build it was compiled in.
 */
#ifndef CH09_GLASS_LIMITS_H
#define CH09_GLASS_LIMITS_H

#include <stdio.h>

/* Prints the measurements, a line each, "# ..." lines naming the columns. */
void glass_limits(FILE *out);

#endif
