/* scene_build.h - building scene descriptions in code.
 *
 * The built-in scene of each renderer is made with these, so that it goes
 * through exactly the same path as a scene read from a file.  Each returns
 * the new item's index, or -1 when out of memory.
 */
#ifndef RT_SCENE_BUILD_H
#define RT_SCENE_BUILD_H

#include "scene.h"

int scene_add_shader(scene *s, scene_shader shader);
int scene_add_surface(scene *s, scene_surface surface);
int scene_add_light(scene *s, scene_light light);
/* These two take over what they are given: the mesh's arrays and the
 * texture's texels (allocated with malloc) are freed by scene_free. */
int scene_add_mesh(scene *s, mesh m);
int scene_add_texture(scene *s, scene_texture texture);

/* A shader with the defaults of docs/scenes.md: white, exponent 1, eta 1.5, no texture. */
scene_shader scene_default_shader(shader_kind kind);
/* The same as an initializer, for a constant. */
#define SCENE_SHADER_DEFAULTS(k)                                                                                   \
    {.kind = (k), .diffuse_color = {1, 1, 1}, .specular_color = {1, 1, 1}, .exponent = 1,                        \
     .refractive_index = (real)1.5, .texture = -1}

#endif
