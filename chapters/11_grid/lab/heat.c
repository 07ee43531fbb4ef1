/* heat.c - chapter 11's lab: a count per pixel as a colour. */
#include "11_grid/lab/heat.h"

#include "display.h"

color heat_color(uint64_t count, int max)
{
    static const real stops[5][3] = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}};
    real x = max > 0 ? (real)count / (real)max : 1;
    if (x > 1)
        x = 1;
    real f = 4 * x;
    int k = (int)f;
    if (k > 3)
        k = 3;
    real w = f - (real)k, c[3];
    for (int a = 0; a < 3; a++) /* blend the displayed values, then undo the display's gamma */
        c[a] = real_pow(stops[k][a] + w * (stops[k + 1][a] - stops[k][a]), (real)DISPLAY_GAMMA);
    return color_make(c[0], c[1], c[2]);
}
