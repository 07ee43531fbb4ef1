/* shade_interp.h - chapter 10: the shading of chapters 05-09 with the interpolated normal as n and a
 * textured shader's k_d read at the point's (u, v) (README, "The shade function"). */
#ifndef CH10_SHADE_INTERP_H
#define CH10_SHADE_INTERP_H

#include "09_refraction/shade_glass.h"
#include "10_interpolation/shading_normal.h"
#include "10_interpolation/texture.h"

typedef enum { NORMALS_INTERPOLATED, NORMALS_GEOMETRIC } normal_source; /* geometric: the mesh's vn ignored */
typedef enum { BELOW_FLIP, BELOW_KEEP } below_policy; /* a mirror direction below the geometric surface */
extern const char *const texture_filter_names[]; /* --texture-filter's words, in texture_filter's order */

/* The knobs of chapter 10: chapter 09's, then its own three. */
typedef struct interp_knobs {
    glass_knobs earlier; /* chapters 06-09: --shadow-eps, --phong, --depth, --min-weight, --fresnel */
    int normals;        /* a normal_source: --normals */
    int filter;         /* a texture_filter: --texture-filter */
    int below;          /* a below_policy: --below-surface */
} interp_knobs;

/* The defaults: chapter 09's, interpolated normals, the nearest texel (the course's images), flipped. */
#define INTERP_KNOBS_DEFAULT \
    {.earlier = GLASS_KNOBS_DEFAULT, .normals = NORMALS_INTERPOLATED, .filter = TEXTURE_NEAREST, .below = BELOW_FLIP}

/* A shade_fn: the shading of chapter 09 with the interpolated normal and the
 * textured diffuse colour (tr->knobs.interp, or the defaults). */
color shade_interp(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays);

#endif
