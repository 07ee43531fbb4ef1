/* surface_attributes.c - what a surface of a scene gives a point on it beyond its geometry. */
#include "surface_attributes.h"

#include "sphere_uv.h"

const mesh_face *surface_mesh_face(const scene *desc, int surface, int face, const mesh **m)
{
    const scene_surface *s = &desc->surfaces[surface];
    if (s->kind != SURFACE_MESH)
        return NULL;
    *m = &desc->meshes[s->mesh];
    return &(*m)->faces[face];
}

bool surface_sphere_uv(const scene *desc, int surface, vec3 point, mesh_uv *uv)
{
    const scene_surface *s = &desc->surfaces[surface];
    if (s->kind != SURFACE_SPHERE)
        return false;
    *uv = sphere_uv(s->center, s->radius, point);
    return true;
}
