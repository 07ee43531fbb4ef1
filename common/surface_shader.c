/* surface_shader.c - the shader a surface of a scene is shaded with. */
#include "surface_shader.h"

#include "scene_build.h"

const scene_shader *surface_shader(const scene *desc, int shader)
{
    static const scene_shader white = SCENE_SHADER_DEFAULTS(SHADER_LAMBERTIAN);
    return shader >= 0 ? &desc->shaders[shader] : &white;
}
