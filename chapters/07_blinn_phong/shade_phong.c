/* shade_phong.c - chapter 07: the shade function of the Blinn-Phong stage. */
#include "07_blinn_phong/shade_phong.h"
#include "exercise.h"

#include "05_lambert/lambert.h"
#include "05_lambert/shade_lambert.h"
#include "06_shadows/shade_shadows.h"
#include "06_shadows/shadow.h"

phong_form tracer_phong_form(const tracer *tr)
{
    static const phong_knobs defaults = PHONG_KNOBS_DEFAULT;
    return (phong_form)(tr->knobs ? (const phong_knobs *)tr->knobs : &defaults)->form;
}

/* snippet: light_contribution */
color light_contribution(const tracer *tr, const shading_point *sp, const scene_shader *shader,
                         const scene_light *light)
{
    color L = lambert(shader->diffuse_color, sp->hit.point, sp->n, light); /* chapter 05 */
    if (shader->kind == SHADER_PHONG) /* no specular work for a Lambertian shader */
        L = color_add(L, blinn_phong_specular(shader->specular_color, shader->exponent, sp->hit.point, sp->n, sp->v,
                                              light, tracer_phong_form(tr)));
    return L;
}
/* end snippet */

/* snippet: shade_phong */
color shade_phong(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    const scene_shader *shader = hit_shader(tr->desc, &sp->hit);
    if (shader->kind == SHADER_RGB_NORMALS) /* a geometry check, not lit */
        return shade_lambert(tr, sp, depth, rays);
    color result = tr->desc->ambient;
    /* TODO lights: the lecture's loop over the lights:
     *     for light in lights
     *         if (shadow ray not blocked): result += shading contribution
     * for each of the scene's lights (tr->desc->lights, tr->desc->n_lights):
     * skip a light behind the surface without casting a shadow ray
     * (light_in_front, chapter 06), ask light_blocked (chapter 06, with the
     * policy tracer_eps(tr)), and add light_contribution to result. */
    EXERCISE_STUB("07_blinn_phong", "shade_phong.c", "lights"); /* delete this line when done */
    return result;
}
/* end snippet */
