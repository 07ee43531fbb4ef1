/* A correct chapter 05 written otherwise than the reference (tools/hostile.sh):
 * it must get full marks and not be flagged as the reference's code. */
#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    vec3 to_light = vec3_sub(light->position, point);
    real r2 = vec3_dot(to_light, to_light);
    real n_dot = vec3_dot(n, to_light); /* r cos(theta) */
    if (!(n_dot > 0))
        return color_make(0, 0, 0);
    real falloff = n_dot / (r2 * real_sqrt(r2)); /* cos(theta) / r^2 */
    return color_make(k_d.r * light->intensity.r * falloff, k_d.g * light->intensity.g * falloff,
                      k_d.b * light->intensity.b * falloff);
}
