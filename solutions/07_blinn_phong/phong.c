/* phong.c - chapter 07: the specular term of Blinn-Phong shading. */
#include "07_blinn_phong/phong.h"

const char *const phong_form_names[] = {"course", "lecture", NULL};

/* snippet: half_vector */
vec3 half_vector(vec3 v, vec3 l)
{
    /* EXERCISE half: the lecture's half vector, the bisector of v and l:
     *     h = (v + l) / |v + l|
     * v and l are unit vectors, so v + l points half-way between them.  (When
     * l = -v, the light straight behind the surface seen head-on, v + l is 0
     * and h has no direction: that case never reaches here, since the light
     * is then behind the surface.) */
    return vec3_normalize(vec3_add(v, l));
    /* STUB
    (void)v;
    return l;
    END EXERCISE */
}
/* end snippet */

/* snippet: blinn_phong_specular */
color blinn_phong_specular(color k_s, real p, vec3 point, vec3 n, vec3 v, const scene_light *light,
                           phong_form form)
{
    /* EXERCISE specular: the specular term of one point light:
     *     course:  k_s max(0, n . h)^p I / r^2
     *     lecture: k_s max(0, n . h)^p max(0, n . l) I / r^2
     * with r = |light.pos - point|, l = (light.pos - point) / r and
     * h = half_vector(v, l).  real_pow(x, p) is x^p.  Channel by channel:
     * color_mul(k_s, I). */
    vec3 to_light = vec3_sub(light->position, point);
    real r2 = vec3_length_squared(to_light);           /* r^2 */
    vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));  /* unit, towards the light */
    vec3 h = half_vector(v, l);
    real highlight = real_pow(real_fmax(0, vec3_dot(n, h)), p); /* max(0, n . h)^p */
    if (form == PHONG_LECTURE)
        highlight *= real_fmax(0, vec3_dot(n, l)); /* the modified Blinn-Phong's cosine */
    return color_scale(color_mul(k_s, light->intensity), highlight / r2);
    /* STUB
    (void)k_s;
    (void)p;
    (void)point;
    (void)n;
    (void)v;
    (void)light;
    (void)form;
    return color_make(0, 0, 0);
    END EXERCISE */
}
/* end snippet */
