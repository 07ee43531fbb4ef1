/* shade_lambert.c - chapter 05: the shade function of the Lambert stage. */
#include "05_lambert/shade_lambert.h"

#include "04_many_shapes/flat_shading.h"
#include "05_lambert/lambert.h"
#include "explain.h"

color shade_lambert(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    (void)depth; /* no ray leaves the surface here: nothing to count */
    (void)rays;
    if (sp->shader->kind == SHADER_RGB_NORMALS) /* a geometry check, not lit: chapter 04's colour */
        return flat_color(tr->desc, &sp->hit);
    if (tr->desc->n_lights == 0)
        return color_make(0, 0, 0);
    /* Surface.shade(ray, point, normal, light) with the lecture's one light */
    color L_d = lambert(sp->shader->diffuse_color, sp->hit.point, sp->n, &tr->desc->lights[0]);
    EXPLAIN(explain_light(&tr->desc->lights[0], sp->hit.point, sp->n, sp->v, L_d, false, L_d));
    return L_d;
}
