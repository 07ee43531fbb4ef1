/* phong.c - chapter 07: the specular term of Blinn-Phong shading. */
#include "07_blinn_phong/phong.h"

const char *const phong_form_names[] = {"course", "lecture", NULL};

color blinn_phong_specular(color k_s, real p, vec3 point, vec3 n, vec3 v, const scene_light *light,
                           phong_form form)
{
    /* EXERCISE specular: the whole specular term of one point light, of either form, channel by channel
     * (README, "Specular shading"); p may be any real number, not only an integer. */
    vec3 to_light = vec3_sub(light->position, point);
    real r2 = vec3_length_squared(to_light);           /* r^2 */
    vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));  /* unit, towards the light */
    vec3 h = vec3_normalize(vec3_add(v, l));           /* the half vector, bisector of v and l */
    real highlight = real_pow(real_fmax(0, vec3_dot(n, h)), p); /* max(0, n . h)^p */
    if (form == PHONG_LECTURE)
        highlight *= real_fmax(0, vec3_dot(n, l)); /* the modified Blinn-Phong's cosine */
    return color_scale(color_mul(k_s, light->intensity), highlight / r2);
    /* STUB
    (void)k_s, (void)p, (void)point, (void)n, (void)v, (void)light, (void)form;
    return color_make(0, 0, 0);
    END EXERCISE */
}
