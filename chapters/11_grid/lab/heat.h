/* heat.h - chapter 11's lab: a count per pixel as a colour, for the grid's figures.
 *
 * The scale runs through five colours, evenly spaced in count:
 *     0 black,  max/4 blue,  max/2 red,  3 max/4 yellow,  max (or more) white,
 * blended in between.  The colours are the displayed ones: heat_color
 * returns the radiance that the display encoding (display.h, gamma 2.2 at
 * exposure 1) turns into them.
 */
#ifndef CH11_LAB_HEAT_H
#define CH11_LAB_HEAT_H

#include <stdint.h>

#include "color.h"

color heat_color(uint64_t count, int max);

#endif
