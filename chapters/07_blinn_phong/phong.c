/* phong.c - chapter 07: the specular term of Blinn-Phong shading. */
#include "07_blinn_phong/phong.h"
#include "exercise.h"

const char *const phong_form_names[] = {"course", "lecture", NULL};

/* snippet: half_vector */
vec3 half_vector(vec3 v, vec3 l)
{
    /* TODO half: the lecture's half vector, the bisector of v and l:
     *     h = (v + l) / |v + l|
     * v and l are unit vectors, so v + l points half-way between them.  (When
     * l = -v, the light straight behind the surface seen head-on, v + l is 0
     * and h has no direction: that case never reaches here, since the light
     * is then behind the surface.) */
    EXERCISE_STUB("07_blinn_phong", "phong.c", "half"); /* delete this line when done */
    (void)v;
    return l;
}
/* end snippet */

/* snippet: blinn_phong_specular */
color blinn_phong_specular(color k_s, real p, vec3 point, vec3 n, vec3 v, const scene_light *light,
                           phong_form form)
{
    /* TODO specular: the specular term of one point light:
     *     course:  k_s max(0, n . h)^p I / r^2
     *     lecture: k_s max(0, n . h)^p max(0, n . l) I / r^2
     * with r = |light.pos - point|, l = (light.pos - point) / r and
     * h = half_vector(v, l).  real_pow(x, p) is x^p.  Channel by channel:
     * color_mul(k_s, I). */
    EXERCISE_STUB("07_blinn_phong", "phong.c", "specular"); /* delete this line when done */
    (void)k_s;
    (void)p;
    (void)point;
    (void)n;
    (void)v;
    (void)light;
    (void)form;
    return color_make(0, 0, 0);
}
/* end snippet */
