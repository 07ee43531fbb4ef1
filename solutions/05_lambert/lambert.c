/* lambert.c - chapter 05: diffuse light from one point source. */
#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    /* EXERCISE lambert: the radiance L_d that a matte surface with coefficient k_d at `point`, unit
     * normal n, reflects from one point light, channel by channel (README, "Point lights"). */
    vec3 to_light = vec3_sub(light->position, point);
    real r2 = vec3_length_squared(to_light);       /* r^2 */
    vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2)); /* l = (light.pos - point) / r */
    real cos_theta = real_fmax(0, vec3_dot(n, l)); /* max(0, n . l) */
    return color_scale(color_mul(k_d, light->intensity), cos_theta / r2);
    /* STUB
    (void)k_d, (void)point, (void)n, (void)light;
    return color_make(0, 0, 0);
    END EXERCISE */
}
