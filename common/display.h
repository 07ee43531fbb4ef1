/* display.h - from linear radiance to 8-bit display values.
 *
 * docs/scenes.md, measured from the course's reference images:
 *     byte = round(255 * clamp((exposure * L)^(1/2.2), 0, 1))   per channel.
 */
#ifndef RT_DISPLAY_H
#define RT_DISPLAY_H

#include <stdint.h>

#include "real.h"

#define DISPLAY_GAMMA 2.2

/* One channel.  NaN encodes as 0 so that a numerical failure shows as black
 * instead of as undefined behaviour in the conversion. */
uint8_t display_encode(real L, real exposure);

#endif
