/* face_query.c - chapter 10: which mesh face a hit lies on. */
#include "10_interpolation/face_query.h"

#include <stdio.h>
#include <stdlib.h>

bool face_query_closest_hit(const void *accel, ray r, real t_min, real t_max, hit_record *hit)
{
    const face_query *fq = accel;
    return fq->inner.closest_hit(fq->inner.accel, r, t_min, t_max, hit);
}

static void face_query_release(void *owned)
{
    face_query *fq = owned;
    if (!fq)
        return;
    if (fq->inner.release)
        fq->inner.release(fq->inner.owned);
    free(fq->first);
    free(fq);
}

int face_query_build(const surface_list *list, const scene *desc, build_query_fn inner, hit_query *q, char *err,
                     size_t err_size)
{
    const char *path = scene_name(desc);
    face_query *fq = calloc(1, sizeof *fq);
    if (!fq || !(fq->first = malloc(sizeof *fq->first * (size_t)(desc->n_surfaces > 0 ? desc->n_surfaces : 1)))) {
        free(fq);
        snprintf(err, err_size, "%s: out of memory for the face table", path);
        return -1;
    }
    fq->desc = desc;
    for (int k = 0; k < desc->n_surfaces; k++)
        fq->first[k] = -1;
    /* The list holds each scene surface's shapes side by side, in order. */
    for (int i = list->n - 1; i >= 0; i--)
        fq->first[list->items[i].source] = i;
    if ((inner ? inner : hit_query_linear)(list, desc, &fq->inner, err, err_size) != 0) {
        face_query_release(fq);
        return -1;
    }
    *q = (hit_query){
        .closest_hit = face_query_closest_hit,
        .accel = fq,
        .owned = fq,
        .release = face_query_release,
    };
    return 0;
}

/* snippet: face_of_hit */
const mesh_face *face_of_hit(const void *accel, const hit_record *hit, const mesh **m)
{
    const face_query *fq = accel;
    const scene_surface *s = &fq->desc->surfaces[hit->source];
    if (s->kind != SURFACE_MESH)
        return NULL;
    *m = &fq->desc->meshes[s->mesh];
    return &(*m)->faces[hit->surface - fq->first[hit->source]];
}
/* end snippet */
