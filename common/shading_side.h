/* shading_side.h - a shading normal on the viewer's side of the surface, and
 * its mirror direction above it.
 *
 * The geometric normal n_g (turned towards the viewer) decides the side; a
 * shading normal n_s (an interpolated one, say) is put on that side.  About a
 * tilted n_s the mirror direction r = 2 (n_s . v) n_s - v can point below the
 * geometric surface; mirrored back above it, r' = r - 2 (r . n_g) n_g, it is
 * the mirror direction of v about n' = normalize(v + r') (chapter 10's README,
 * "A mirror direction below the surface").
 */
#ifndef SHADING_SIDE_H
#define SHADING_SIDE_H

#include "vec3.h"

/* n_s, or -n_s when n_s . n_g < 0. */
vec3 shading_normal(vec3 n_s, vec3 n_g);

/* n_s when r . n_g >= 0, else normalize(v + r'): the normal about which v
 * reflects above the surface.  n_s, n_g and v are unit vectors, n_g towards
 * the viewer, v . n_g >= 0. */
vec3 mirror_above(vec3 n_s, vec3 n_g, vec3 v);

#endif
