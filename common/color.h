/* color.h - linear RGB radiance.
 *
 * Colours stay linear (proportional to light) until the very end, where
 * display.h encodes them for the screen.  They have their own type so that a
 * colour is never passed where a point is expected.
 */
#ifndef RT_COLOR_H
#define RT_COLOR_H

#include "real.h"

typedef struct {
    real r, g, b;
} color;

static inline color color_make(real r, real g, real b) { return (color){r, g, b}; }
static inline color color_add(color a, color b) { return (color){a.r + b.r, a.g + b.g, a.b + b.b}; }
static inline color color_scale(color a, real s) { return (color){s * a.r, s * a.g, s * a.b}; }
static inline color color_mul(color a, color b) { return (color){a.r * b.r, a.g * b.g, a.b * b.b}; }

#endif
