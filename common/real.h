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
#define REAL_NAME "float"
#define real_sqrt sqrtf
#define real_abs fabsf
#define real_pow powf
#define real_floor floorf
#define real_fmax fmaxf
#define real_fmin fminf
#else
typedef double real;
#define REAL_EPSILON DBL_EPSILON
#define REAL_MAX DBL_MAX
#define REAL_NAME "double"
#define real_sqrt sqrt
#define real_abs fabs
#define real_pow pow
#define real_floor floor
#define real_fmax fmax
#define real_fmin fmin
#endif

#define REAL_INFINITY ((real)INFINITY)

#endif
