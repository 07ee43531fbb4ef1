/* lambert.c - chapter 05: diffuse light from one point source. */
#include "05_lambert/lambert.h"
#include "exercise.h"

/* snippet: lambert */
color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    /* TODO lambert: the lecture's Lambertian shading with k_d = R / pi:
     *     L_d = k_d max(0, n . l) I / r^2
     * where r = |light.pos - point| is the distance to the light and
     * l = (light.pos - point) / r the unit vector towards it.  The irradiance
     * max(0, n . l) I / r^2 is Lambert's cosine law (a surface tilted by theta
     * away from the light catches cos(theta) of what it catches facing it)
     * and the point source's falloff (its power spreads over a sphere of area
     * 4 pi r^2).  Multiply channel by channel: color_mul(k_d, I). */
    EXERCISE_STUB("05_lambert", "lambert.c", "lambert"); /* delete this line when done */
    (void)k_d;
    (void)point;
    (void)n;
    (void)light;
    return color_make(0, 0, 0);
}
/* end snippet */
