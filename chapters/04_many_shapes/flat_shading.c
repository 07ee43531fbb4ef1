/* flat_shading.c - chapter 04: one flat colour per surface. */
#include "04_many_shapes/flat_shading.h"

#include "04_many_shapes/closest_hit.h"
#include "explain.h"
#include "surface_shader.h"

/* snippet: flat_color */
color flat_color(const scene *desc, const hit_record *hit)
{
    const scene_shader *shader = surface_shader(desc, hit->shader); /* none: white Lambertian */
    if (shader->kind == SHADER_RGB_NORMALS) { /* (n + 1) / 2: each component from [-1, 1] to [0, 1] */
        vec3 n = hit->normal;
        return color_make((n.x + 1) / 2, (n.y + 1) / 2, (n.z + 1) / 2);
    }
    return shader->diffuse_color;
}

color trace_flat(const surface_list *list, const scene *desc, ray r, real t_min, real t_max)
{
    hit_record hit;
    if (!surfaces_intersect(list, r, t_min, t_max, &hit))
        return desc->back_color;
    EXPLAIN(explain_closest(hit.surface, hit.source, hit.t, hit.point));
    return flat_color(desc, &hit);
}
/* end snippet */
