/* sphere_uv.h - chapter 10: the course's texture coordinates of a sphere.
 *
 * A sphere has no vertices to carry texture coordinates; they come from the
 * direction of the point from the centre, as longitude and latitude.  With
 * the unit vector (x, y, z) = (point - center) / radius, the pole on +y:
 *
 *     u = 1/2 + atan2(x, z) / (2 pi)     longitude, once around the y axis
 *     v = 1/2 + asin(y) / pi             latitude, 0 at the south pole, 1 at the north
 *
 * (measured against the course's images: the README says how.)
 */
#ifndef CH10_SPHERE_UV_H
#define CH10_SPHERE_UV_H

#include "mesh.h"
#include "vec3.h"

/* The texture coordinates of `point` on the sphere (center, radius). */
mesh_uv sphere_uv(vec3 center, real radius, vec3 point);

#endif
