/* scene_surfaces.c - chapter 04: the surface list of a scene description. */
#include "04_many_shapes/scene_surfaces.h"

#include <stdio.h>

#include "04_many_shapes/box.h"

/* Appends triangle `face` of scene surface k (a Box's or a Mesh's); -1 when out of memory. */
static int add_face(surface_list *list, triangle tri, int shader, int k, int face)
{
    int i = surface_list_add_triangle(list, tri, shader, k);
    if (i >= 0)
        list->items[i].face = face;
    return i;
}

/* Appends the surfaces that scene surface k becomes; -1 when out of memory. */
static int add_scene_surface(surface_list *list, const scene *desc, int k)
{
    const scene_surface *s = &desc->surfaces[k];
    switch (s->kind) {
    case SURFACE_SPHERE:
        return surface_list_add_sphere(list, (sphere){s->center, s->radius}, s->shader, k) < 0 ? -1 : 0;
    case SURFACE_TRIANGLE:
        return surface_list_add_triangle(list, (triangle){s->v0, s->v1, s->v2}, s->shader, k) < 0 ? -1 : 0;
    case SURFACE_BOX: {
        triangle faces[BOX_TRIANGLES];
        box_triangles(s->min_pt, s->max_pt, faces);
        for (int f = 0; f < BOX_TRIANGLES; f++)
            if (add_face(list, faces[f], s->shader, k, f) < 0)
                return -1;
        return 0;
    }
    case SURFACE_MESH: {
        const mesh *m = &desc->meshes[s->mesh];
        for (int f = 0; f < m->n_faces; f++) {
            const int *v = m->faces[f].v;
            triangle tri = {m->positions[v[0]], m->positions[v[1]], m->positions[v[2]]};
            if (add_face(list, tri, s->shader, k, f) < 0)
                return -1;
        }
        return 0;
    }
    }
    return 0;
}

int surface_list_from_scene(surface_list *list, const scene *desc, char *err, size_t err_size)
{
    for (int k = 0; k < desc->n_surfaces; k++) {
        if (add_scene_surface(list, desc, k) != 0) {
            snprintf(err, err_size, "%s:%d: out of memory for the surface list", scene_name(desc),
                     desc->surfaces[k].line);
            return -1;
        }
    }
    return 0;
}
