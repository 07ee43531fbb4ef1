/* shade_glazed.c - chapter 08: the shade function of the mirror stage. */
#include "08_mirrors/shade_glazed.h"

#include "08_mirrors/mirror.h"

color shade_glazed(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    color L = shade_phong(tr, sp, depth, rays); /* L_a + L_r: chapter 07 */
    const scene_shader *shader = sp->shader;
    color k_m = shader->mirror_coefficient;
    if (shader->kind == SHADER_RGB_NORMALS || (k_m.r == 0 && k_m.g == 0 && k_m.b == 0))
        return L; /* no mirror: no mirror ray */
    return color_add(L, color_mul(k_m, mirror_radiance(tr, sp, k_m, depth, rays))); /* + k_m L_m */
}
