#include "scene_build.h"

#include <stdlib.h>

/* Appends one element of `size` bytes to *array of *count elements. */
static int append(void **array, int *count, const void *item, size_t size)
{
    char *bigger = realloc(*array, (size_t)(*count + 1) * size);
    if (!bigger)
        return -1;
    for (size_t k = 0; k < size; k++)
        bigger[(size_t)*count * size + k] = ((const char *)item)[k];
    *array = bigger;
    return (*count)++;
}

int scene_add_shader(scene *s, scene_shader shader)
{
    shader.name = NULL; /* built-in shaders are referred to by index */
    return append((void **)&s->shaders, &s->n_shaders, &shader, sizeof shader);
}

int scene_add_surface(scene *s, scene_surface surface)
{
    return append((void **)&s->surfaces, &s->n_surfaces, &surface, sizeof surface);
}

int scene_add_light(scene *s, scene_light light) { return append((void **)&s->lights, &s->n_lights, &light, sizeof light); }

int scene_add_mesh(scene *s, mesh m) { return append((void **)&s->meshes, &s->n_meshes, &m, sizeof m); }

int scene_add_texture(scene *s, scene_texture texture)
{
    texture.name = NULL; /* built-in textures are referred to by index */
    return append((void **)&s->textures, &s->n_textures, &texture, sizeof texture);
}

scene_shader scene_default_shader(shader_kind kind)
{
    return (scene_shader)SCENE_SHADER_DEFAULTS(kind);
}
