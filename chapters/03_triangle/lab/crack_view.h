/* crack_view.h - chapter 03's lab: the cracks of a closed mesh, seen from inside.
 *
 * The camera stands inside the unit icosahedron.  Each pixel near an edge
 * casts CRACK_RAYS rays aimed exactly at points of its stretch of that edge
 * (or at the vertex, near a corner): grey when all of them hit a triangle,
 * red when one slips through.  The faces elsewhere are the barycentric
 * colours, dark.
 */
#ifndef CH03_LAB_CRACK_VIEW_H
#define CH03_LAB_CRACK_VIEW_H

#include <stdint.h>

#include "03_triangle/triangle_stage.h"

/* A wide-angle camera inside the unit icosahedron at the origin; 0, or -1
 * when out of memory. */
int crack_scene(scene *desc);

/* The pixel whose eye ray is r, the aimed rays cast with s->test and
 * counted in *rays. */
color crack_color(const triangle_stage *s, ray r, uint64_t *rays);

/* renderer.h's sample: crack_color of the pixel's eye ray. */
color crack_sample(const void *prepared, real u, real v, uint64_t *rays);

#endif
