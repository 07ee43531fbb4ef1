/* vec3.h - three-component vectors: points, directions and normals.
 *
 * Small inline functions, one operation each, so that the intersection code
 * reads like the lecture's equations: vec3_dot(d, p) is d . p.
 */
#ifndef RT_VEC3_H
#define RT_VEC3_H

#include <stdbool.h>

#include "real.h"

typedef struct {
    real x, y, z;
} vec3;

static inline vec3 vec3_make(real x, real y, real z) { return (vec3){x, y, z}; }
static inline vec3 vec3_add(vec3 a, vec3 b) { return (vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static inline vec3 vec3_sub(vec3 a, vec3 b) { return (vec3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static inline vec3 vec3_neg(vec3 a) { return (vec3){-a.x, -a.y, -a.z}; }
static inline vec3 vec3_scale(vec3 a, real s) { return (vec3){s * a.x, s * a.y, s * a.z}; }
/* Component-wise product (for colours and scale factors). */
static inline vec3 vec3_mul(vec3 a, vec3 b) { return (vec3){a.x * b.x, a.y * b.y, a.z * b.z}; }

static inline real vec3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/* a x b, right-handed: (1,0,0) x (0,1,0) = (0,0,1). */
static inline vec3 vec3_cross(vec3 a, vec3 b)
{
    return (vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

static inline real vec3_length_squared(vec3 a) { return vec3_dot(a, a); }

/* The largest absolute component: a cheap scale for relative tolerances. */
static inline real vec3_max_abs(vec3 a)
{
    /* fmax written out (a NaN component is passed over, as fmax does): it is
     * called on every hit, and the library call costs more than the test */
    real x = real_abs(a.x), y = real_abs(a.y), z = real_abs(a.z);
    real m = x > y || y != y ? x : y;
    return m > z || z != z ? m : z;
}

/* a divided by its largest absolute component: that component becomes +-1,
 * so a . a is between 1 and 3 (a must not be zero). */
static inline vec3 vec3_divide_by_max_abs(vec3 a)
{
    real m = vec3_max_abs(a);
    return (vec3){a.x / m, a.y / m, a.z / m};
}

/* |a|.  When a . a overflows or falls below the normal reals (components
 * beyond about 1e154 or under 1e-154 in double), |a| is computed from a
 * scaled by its largest component instead; otherwise sqrt(a . a), so that
 * ordinary vectors give the same bits as always. */
static inline real vec3_length(vec3 a)
{
    real squared = vec3_dot(a, a);
    if (squared >= REAL_MIN && squared <= REAL_MAX)
        return real_sqrt(squared);
    real m = vec3_max_abs(a);
    if (m == 0 || !isfinite(m))
        return m; /* 0 for the zero vector; infinity or NaN as given */
    return m * real_sqrt(vec3_dot(vec3_divide_by_max_abs(a), vec3_divide_by_max_abs(a)));
}

/* a / |a|, with the same care as vec3_length for huge and tiny vectors.  The
 * zero vector has no direction: callers check the length first where a zero
 * vector can occur (vec3_normalize of zero gives NaNs). */
static inline vec3 vec3_normalize(vec3 a)
{
    real squared = vec3_dot(a, a);
    if (squared >= REAL_MIN && squared <= REAL_MAX)
        return vec3_scale(a, (real)1 / real_sqrt(squared));
    vec3 b = vec3_divide_by_max_abs(a);
    return vec3_scale(b, (real)1 / real_sqrt(vec3_dot(b, b)));
}

/* a 2^e, exactly (a power of two moves only the exponents) unless a
 * component leaves the range of reals. */
static inline vec3 vec3_ldexp(vec3 a, int e)
{
    return (vec3){(real)ldexp(a.x, e), (real)ldexp(a.y, e), (real)ldexp(a.z, e)};
}

/* real_scale_exponent of a's largest |component|: 0 for the usual vectors
 * (the max needs no care for NaN here: a NaN ends as a miss either way). */
static inline int vec3_scale_exponent(vec3 a)
{
    real x = real_abs(a.x), y = real_abs(a.y), z = real_abs(a.z);
    real m = x > y ? x : y;
    return real_scale_exponent(m > z ? m : z);
}

static inline bool vec3_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

#endif
