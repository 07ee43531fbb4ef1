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

/* A shader with the defaults of docs/scenes.md: white, exponent 1, eta 1.5, no texture. */
scene_shader scene_default_shader(shader_kind kind);

#endif
