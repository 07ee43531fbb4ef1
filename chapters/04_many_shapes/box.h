/* box.h - chapter 04: an axis-aligned box as 12 triangles.
 *
 * A <surface type="Box"> of the scene format (docs/scenes.md) is given by two
 * corners, minPt and maxPt.
 * Its six faces are two triangles each, wound counter-clockwise seen from
 * outside, so that every triangle_normal() (b - a) x (c - a) points out of
 * the box, as the RGBNormals images of the course show.
 */
#ifndef CH04_BOX_H
#define CH04_BOX_H

#include "03_triangle/triangle.h"

#define BOX_TRIANGLES 12

/* The faces in the order -x, +x, -y, +y, -z, +z, two triangles each.
 * min_pt <= max_pt component-wise (the scene reader sorts them). */
void box_triangles(vec3 min_pt, vec3 max_pt, triangle out[BOX_TRIANGLES]);

#endif
