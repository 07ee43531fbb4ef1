/* face_query.h - chapter 10: which mesh face a hit lies on.
 *
 * Chapter 04 turns a Mesh into one triangle per face, in the file's order,
 * and a hit names the triangle by its index in the surface list
 * (hit.surface) and the scene surface it came from (hit.source).  The
 * per-vertex normals and texture coordinates are the mesh's, per face; so
 * this chapter needs, for a triangle hit, its face:
 *
 *     face = hit.surface - (index in the list of the source's first triangle)
 *
 * A face_query is the renderer's closest-hit query (chapter 04's linear scan,
 * or chapter 11's grid) with that table beside it: the tracer's `accel`
 * becomes the face_query, whose closest_hit asks the inner query and changes
 * nothing of what it finds.  The shade function of chapter 10 finds the table
 * through tr->accel (face_of_hit), whatever the inner query is, and
 * path_next's copies of the tracer keep it.
 */
#ifndef CH10_FACE_QUERY_H
#define CH10_FACE_QUERY_H

#include <stddef.h>

#include "05_lambert/shading_stage.h"

typedef struct {
    hit_query inner; /* the query that finds the hits */
    const scene *desc;
    int *first;      /* first[k]: list index of scene surface k's first surface */
} face_query;

/* A closest_hit_fn over a face_query: the inner query's answer, unchanged. */
bool face_query_closest_hit(const void *accel, ray r, real t_min, real t_max, hit_record *hit);

/* Builds the inner query with `inner` (NULL: chapter 04's linear scan) and
 * the table over `list`, into *q (a closest_hit of face_query_closest_hit;
 * q->release frees both).  Returns 0, or -1 with "path: problem" in err. */
int face_query_build(const surface_list *list, const scene *desc, build_query_fn inner, hit_query *q, char *err,
                     size_t err_size);

/* The mesh face a hit lies on: the mesh in *m and the face, or NULL when the
 * hit is not on a Mesh surface.  accel is a face_query (tracer.accel). */
const mesh_face *face_of_hit(const void *accel, const hit_record *hit, const mesh **m);

#endif
