#include "display.h"

#include <math.h>

uint8_t display_encode(real L, real exposure)
{
    /* Computed in double whatever `real` is, so that the float and the double
     * builds encode the same radiance to the same byte. */
    double x = (double)exposure * (double)L;
    if (!(x > 0)) /* also catches NaN */
        return 0;
    double encoded = pow(x, 1.0 / DISPLAY_GAMMA);
    if (encoded >= 1)
        return 255;
    return (uint8_t)lround(255 * encoded);
}
