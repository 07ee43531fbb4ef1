/* box.h - axis-aligned boxes [lo, hi] and the rounding a grid over them must allow for.
 *
 * A box of surfaces is exact: min and max round nothing.  A point computed
 * in it (a hit p + t d, a cell plane lo_a + i cell_a) is off by a few
 * REAL_EPSILON times the coordinates involved; box_margin and box_ray_slack
 * bound that with room to spare (chapters/11_grid/README.md, "Listing the
 * surfaces" and "Entering the grid").
 */
#ifndef RT_BOX_H
#define RT_BOX_H

#include <stdbool.h>

#include "ray.h"

typedef struct {
    vec3 lo, hi;
} box;

/* Component a of v: x, y, z for a = 0, 1, 2. */
static inline real vec3_axis(vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

box box_empty(void);                          /* lo = +inf, hi = -inf: nothing, the union's identity */
box box_union(box a, box b);                  /* componentwise fmin of the lows, fmax of the highs */
box box_of_sphere(vec3 center, real radius);  /* center -+ |radius| */
box box_of_triangle(vec3 a, vec3 b, vec3 c);  /* the vertices' extremes */
box box_widen(box b, real m);                 /* [lo - m, hi + m] on every axis */
bool box_is_finite(box b);

/* The margin every box of a grid over b is widened by: 64 REAL_EPSILON
 * max(|lo|, |hi|), far more than rounding moves a point computed in b and
 * far less than a cell; 1 when that is 0 (b is the origin) or NaN. */
real box_margin(box b);

/* f clamped to [lowest, highest], then converted: a NaN gives lowest, and an
 * f beyond an int's range never reaches the (undefined) conversion. */
int real_to_index(real f, int lowest, int highest);

/* The ray r against b's slabs: inv_d[a] = 1 / d_a (0 when that is not finite:
 * the ray never crosses a face of axis a), slack[a] = reach |inv_d[a]|.
 * Returns reach = 16 REAL_EPSILON (max|p| + max(|lo|, |hi|)), which bounds
 * in length how far rounding moves a computed crossing; slack[a] bounds it in t. */
real box_ray_slack(box b, ray r, real inv_d[3], real slack[3]);

#endif
