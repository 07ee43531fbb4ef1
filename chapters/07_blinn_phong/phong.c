/* phong.c - chapter 07: the specular term of Blinn-Phong shading. */
#include "07_blinn_phong/phong.h"
#include "exercise.h"

const char *const phong_form_names[] = {"course", "lecture", NULL};

color blinn_phong_specular(color k_s, real p, vec3 point, vec3 n, vec3 v, const scene_light *light,
                           phong_form form)
{
    /* TODO specular: the whole specular term of one point light, of either form, channel by channel
     * (README, "Specular shading"); p may be any real number, not only an integer. */
    EXERCISE_STUB("07_blinn_phong", "phong.c", "specular"); /* delete this line when done */
    (void)k_s, (void)p, (void)point, (void)n, (void)v, (void)light, (void)form;
    return color_make(0, 0, 0);
}
