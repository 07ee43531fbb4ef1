#include "scene_cost.h"

#include <stdio.h>

long scene_triangles(const scene *s, unsigned modelled)
{
    long n = 0;
    for (int k = 0; k < s->n_surfaces; k++) {
        const scene_surface *f = &s->surfaces[k];
        if (f->kind == SURFACE_TRIANGLE && (modelled & FEATURE_TRIANGLES))
            n++;
        else if (f->kind == SURFACE_MESH && (modelled & FEATURE_MESHES))
            n += s->meshes[f->mesh].n_faces;
    }
    return n;
}

void scene_cost_note(const scene *s, unsigned modelled, char *out, size_t out_size)
{
    long n = scene_triangles(s, modelled);
    if (n <= SCENE_MANY_TRIANGLES) {
        out[0] = '\0';
        return;
    }
    snprintf(out, out_size,
             "%ld triangles, and every ray tests each of them (no acceleration structure before chapter 11): "
             "this may take minutes; chapter 11's renderer, with its grid, takes seconds",
             n);
}
