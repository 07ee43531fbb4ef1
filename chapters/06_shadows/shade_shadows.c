/* shade_shadows.c - chapter 06: the shade function of the shadow stage. */
#include "06_shadows/shade_shadows.h"

#include "05_lambert/lambert.h"
#include "05_lambert/shade_lambert.h"
#include "06_shadows/shadow.h"
#include "explain.h"

bool light_in_front(const shading_point *sp, const scene_light *light)
{
    return vec3_dot(sp->n, vec3_sub(light->position, sp->hit.point)) > 0;
}

color shade_shadows(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    const scene_shader *shader = sp->shader;
    if (shader->kind == SHADER_RGB_NORMALS || tr->desc->n_lights == 0)
        return shade_lambert(tr, sp, depth, rays); /* nothing to shadow */
    const scene_light *light = &tr->desc->lights[0];
    if (light_blocked(tr, sp, light->position, tracer_eps(tr), rays)) /* behind the surface, or a shadow */
        return color_make(0, 0, 0);
    color L_d = lambert(shader->diffuse_color, sp->hit.point, sp->n, light);
    EXPLAIN(explain_light(light, sp->hit.point, sp->n, sp->v, L_d, false, L_d));
    return L_d;
}
