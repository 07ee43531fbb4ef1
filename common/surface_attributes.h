/* surface_attributes.h - what a surface of a scene gives a point on it
 * beyond its geometry: the mesh face the point lies on (whose corners may
 * carry normals and texture coordinates), or a sphere's (u, v)
 * (common/sphere_uv.h).
 */
#ifndef RT_SURFACE_ATTRIBUTES_H
#define RT_SURFACE_ATTRIBUTES_H

#include <stdbool.h>

#include "scene.h"

/* Face `face` of surface `surface` of desc, its mesh in *m, when that
 * surface is a Mesh; NULL (and *m untouched) otherwise. */
const mesh_face *surface_mesh_face(const scene *desc, int surface, int face, const mesh **m);

/* True and *uv the sphere's (u, v) at `point` when surface `surface` of
 * desc is a Sphere; false (and *uv untouched) otherwise. */
bool surface_sphere_uv(const scene *desc, int surface, vec3 point, mesh_uv *uv);

#endif
