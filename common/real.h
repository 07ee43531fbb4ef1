/* real.h - the one floating-point type of the renderer.
 *
 * Precision is the first accuracy knob (docs/design.md, "Knobs"): `real` is
 * double by default; `make REAL=float` builds every renderer and test with
 * float instead, side by side in build-float/.  Code never names float or
 * double directly; it uses `real` and the real_* functions below.
 */
#ifndef RT_REAL_H
#define RT_REAL_H

#include <float.h>
#include <math.h>

#ifdef RT_REAL_FLOAT
typedef float real;
#define REAL_EPSILON FLT_EPSILON /* spacing of reals just above 1 */
#define REAL_MAX FLT_MAX
#define REAL_MIN FLT_MIN /* the smallest normal float */
#define REAL_NAME "float"
#define real_sqrt sqrtf
#define real_abs fabsf
#define real_pow powf
#define real_floor floorf
#define real_ceil ceilf
#define real_fmax fmaxf
#define real_fmin fminf
#define real_copysign copysignf
#define real_next_up(x) nextafterf((x), INFINITY) /* the next float above x */
#else
typedef double real;
#define REAL_EPSILON DBL_EPSILON
#define REAL_MAX DBL_MAX
#define REAL_MIN DBL_MIN
#define REAL_NAME "double"
#define real_sqrt sqrt
#define real_abs fabs
#define real_pow pow
#define real_floor floor
#define real_ceil ceil
#define real_fmax fmax
#define real_fmin fmin
#define real_copysign copysign
#define real_next_up(x) nextafter((x), INFINITY) /* the next double above x */
#endif

#define REAL_INFINITY ((real)INFINITY)

/* Lengths between 2^-REAL_SAFE_EXPONENT and 2^REAL_SAFE_EXPONENT can be
 * multiplied four at a time (a ray-sphere discriminant is |d|^2 R^2 in size)
 * without leaving the normal reals, with room for the sums: 2^(4 x 30) is
 * below float's 2^128, 2^(4 x 254) below double's 2^1024.  Data outside
 * that range are scaled by a power of two first (real_scale_exponent), which
 * changes no digit. */
#ifdef RT_REAL_FLOAT
#define REAL_SAFE_EXPONENT 30
#define REAL_SAFE_LOW 0x1p-30f /* 2^-REAL_SAFE_EXPONENT */
#define REAL_SAFE_HIGH 0x1p30f
#else
#define REAL_SAFE_EXPONENT 254
#define REAL_SAFE_LOW 0x1p-254
#define REAL_SAFE_HIGH 0x1p254
#endif

/* 0 when |x| is in the safe range (or x is 0, infinite or NaN: no power of
 * two mends those); else the e of least magnitude for which x / 2^e is in
 * it, just inside its nearer end (moving x no further than needed keeps
 * whatever is divided or multiplied by 2^e along with it, such as a ray's
 * t, as far from its own limits as it can be). */
static inline int real_scale_exponent(real x)
{
    x = real_abs(x);
    if ((x >= REAL_SAFE_LOW && x <= REAL_SAFE_HIGH) || !(x > 0 && x <= REAL_MAX))
        return 0;
    int e; /* x = f 2^e, 1/2 <= f < 1 */
    frexp((double)x, &e);
    return x > REAL_SAFE_HIGH ? e - REAL_SAFE_EXPONENT : e + REAL_SAFE_EXPONENT - 1;
}

/* Whether the whole number x is odd, with no conversion to an integer type
 * (undefined behaviour once x is beyond that type's range, 2^63 for long).
 * Every real of magnitude 2^53 and above (2^24 in float) is even; so are the
 * infinities; NaN is not odd.  x / 2 is exact: x is whole, so not subnormal. */
static inline int real_is_odd(real x)
{
    real half = x / 2;
    return half == half && half != real_floor(half);
}

#endif
