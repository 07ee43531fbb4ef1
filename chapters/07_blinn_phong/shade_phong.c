/* shade_phong.c - chapter 07: the shade function of the Blinn-Phong stage. */
#include "07_blinn_phong/shade_phong.h"
#include "exercise.h"

#include "05_lambert/lambert.h"
#include "05_lambert/shade_lambert.h"
#include "06_shadows/shadow.h"
#include "explain.h"

phong_form tracer_phong_form(const tracer *tr)
{
    const phong_knobs defaults = PHONG_KNOBS_DEFAULT;
    return (phong_form)(tr->knobs.phong ? tr->knobs.phong : &defaults)->form;
}

color light_contribution(const tracer *tr, const shading_point *sp, const scene_shader *shader,
                         const scene_light *light)
{
    color L_d = lambert(shader->diffuse_color, sp->hit.point, sp->n, light); /* chapter 05 */
    if (shader->kind != SHADER_PHONG) { /* no specular work for a Lambertian shader */
        EXPLAIN(explain_light(light, sp->hit.point, sp->n, sp->v, L_d, false, L_d));
        return L_d;
    }
    color L_s = blinn_phong_specular(shader->specular_color, shader->exponent, sp->hit.point, sp->n, sp->v, light,
                                     tracer_phong_form(tr));
    EXPLAIN(explain_light(light, sp->hit.point, sp->n, sp->v, L_d, true, L_s));
    return color_add(L_d, L_s);
}

color shade_phong(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    const scene_shader *shader = sp->shader;
    if (shader->kind == SHADER_RGB_NORMALS) /* a geometry check, not lit */
        return shade_lambert(tr, sp, depth, rays);
    /* TODO lights: the radiance of the lecture's model at sp: the ambient light and every light of the
     * scene that is not blocked, each adding its light_contribution (README, "Many lights and ambient light";
     * which lights are blocked: chapter 06, with the tracer's policy). */
    EXERCISE_STUB("07_blinn_phong", "shade_phong.c", "lights"); /* delete this line when done */
    (void)rays;
    color result = color_make(0, 0, 0);
    EXPLAIN(explain_ambient(tr->desc->ambient));
    return result;
}
