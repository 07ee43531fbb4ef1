/* lambert.c - chapter 05: diffuse light from one point source. */
#include "05_lambert/lambert.h"
#include "exercise.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    /* TODO lambert: the radiance L_d that a matte surface with coefficient k_d at `point`, unit
     * normal n, reflects from one point light, channel by channel (README, "Point lights"). */
    EXERCISE_STUB("05_lambert", "lambert.c", "lambert"); /* delete this line when done */
    (void)k_d, (void)point, (void)n, (void)light;
    return color_make(0, 0, 0);
}
