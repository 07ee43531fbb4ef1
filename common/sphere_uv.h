/* sphere_uv.h - the course's texture coordinates of a sphere.
 *
 * With the unit vector (x, y, z) = (point - center) / radius, the pole on +y
 * (longitude and latitude; chapter 10's README says how it was measured):
 *
 *     u = 1/2 + atan2(x, z) / (2 pi)        v = 1/2 + asin(y) / pi
 */
#ifndef SPHERE_UV_H
#define SPHERE_UV_H

#include "mesh.h"
#include "vec3.h"

/* The texture coordinates of `point` on the sphere (center, radius): u once
 * around the y axis, v from 0 at the south pole to 1 at the north. */
mesh_uv sphere_uv(vec3 center, real radius, vec3 point);

#endif
