/* surface_shader.h - the shader a surface of a scene is shaded with.
 *
 * A surface names its shader by index into scene.shaders; one without a
 * shader (index -1) is white Lambertian, with the defaults of docs/scenes.md.
 */
#ifndef RT_SURFACE_SHADER_H
#define RT_SURFACE_SHADER_H

#include "scene.h"

/* desc->shaders[shader], or the white Lambertian shader when shader < 0. */
const scene_shader *surface_shader(const scene *desc, int shader);

#endif
