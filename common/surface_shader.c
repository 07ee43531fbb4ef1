/* surface_shader.c - the shader a surface of a scene is shaded with. */
#include "surface_shader.h"

const scene_shader *surface_shader(const scene *desc, int shader)
{
    static const scene_shader white = {
        .kind = SHADER_LAMBERTIAN,
        .diffuse_color = {1, 1, 1},
        .specular_color = {1, 1, 1},
        .exponent = 1,
        .refractive_index = (real)1.5,
        .texture = -1,
    };
    return shader >= 0 ? &desc->shaders[shader] : &white;
}
