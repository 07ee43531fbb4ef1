/* texture_space.c - texture coordinates in texel units. */
#include "texture_space.h"

#define TEXEL_COORDINATE_LIMIT ((real)1099511627776.0) /* 2^40 */

real texel_coordinate(real s, int n)
{
    real x = s * (real)n;
    if (!(x == x))
        return 0;
    return real_fmin(real_fmax(x, -TEXEL_COORDINATE_LIMIT), TEXEL_COORDINATE_LIMIT);
}
