/* scene.c - defaults, freeing and feature lists of scene descriptions.
 * The XML reader itself is in scene_xml.c. */
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void scene_init(scene *s)
{
    *s = (scene){0};
    s->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 0, 0},
        .view_dir = {0, 0, -1},
        .view_up = {0, 1, 0},
        .proj_distance = 1,
        .view_width = 1,
        .view_height = 1,
    };
    s->exposure = 1;
}

const char *scene_name(const scene *s) { return s->path ? s->path : "built-in scene"; }

void scene_free(scene *s)
{
    for (int k = 0; k < s->n_shaders; k++)
        free(s->shaders[k].name);
    for (int k = 0; k < s->n_textures; k++) {
        free(s->textures[k].name);
        free(s->textures[k].image_path);
        texture_image_free(&s->textures[k].image);
    }
    for (int k = 0; k < s->n_meshes; k++)
        mesh_free(&s->meshes[k]);
    free(s->shaders);
    free(s->textures);
    free(s->surfaces);
    free(s->lights);
    free(s->meshes);
    free(s->path);
    scene_init(s);
}

static bool nonzero(color c) { return c.r != 0 || c.g != 0 || c.b != 0; }

unsigned scene_features(const scene *s)
{
    unsigned used = 0;
    static const unsigned surface_feature[] = {
        [SURFACE_SPHERE] = FEATURE_SPHERES,
        [SURFACE_BOX] = FEATURE_BOXES,
        [SURFACE_MESH] = FEATURE_MESHES,
        [SURFACE_TRIANGLE] = FEATURE_TRIANGLES,
    };
    for (int k = 0; k < s->n_surfaces; k++) {
        const scene_surface *surface = &s->surfaces[k];
        used |= surface_feature[surface->kind];
        if (surface->kind == SURFACE_MESH && s->meshes[surface->mesh].n_normals > 0)
            used |= FEATURE_VERTEX_NORMALS;
        if (surface->shader < 0)
            continue;
        const scene_shader *shader = &s->shaders[surface->shader];
        used |= FEATURE_SHADERS;
        if (shader->kind == SHADER_PHONG)
            used |= FEATURE_PHONG;
        if (shader->kind == SHADER_GLASS)
            used |= FEATURE_GLASS;
        if (shader->kind == SHADER_RGB_NORMALS)
            used |= FEATURE_RGB_NORMALS;
        if (nonzero(shader->mirror_coefficient))
            used |= FEATURE_MIRRORS;
        if (shader->texture >= 0)
            used |= FEATURE_TEXTURES;
    }
    if (s->n_lights > 0)
        used |= FEATURE_LIGHTS | FEATURE_SHADOWS;
    if (s->n_lights > 1)
        used |= FEATURE_MANY_LIGHTS;
    if (nonzero(s->ambient))
        used |= FEATURE_AMBIENT;
    return used;
}

void scene_ignored_features(unsigned used, unsigned modelled, char *out, size_t out_size)
{
    static const struct {
        unsigned feature;
        const char *name;
        const char *chapter;
    } names[] = {
        {FEATURE_SPHERES, "spheres", "02"},
        {FEATURE_TRIANGLES, "triangles", "03"},
        {FEATURE_BOXES, "boxes", "04"},
        {FEATURE_MESHES, "meshes", "04"},
        {FEATURE_SHADERS, "surface colours", "04"},
        {FEATURE_RGB_NORMALS, "RGBNormals", "04"},
        {FEATURE_LIGHTS, "lights", "05"},
        {FEATURE_SHADOWS, "shadows", "06"},
        {FEATURE_MANY_LIGHTS, "lights after the first", "07"},
        {FEATURE_PHONG, "Phong highlights", "07"},
        {FEATURE_AMBIENT, "ambient", "07"},
        {FEATURE_MIRRORS, "mirrors", "08"},
        {FEATURE_GLASS, "glass", "09"},
        {FEATURE_VERTEX_NORMALS, "vertex normals", "10"},
        {FEATURE_TEXTURES, "textures", "10"},
    };
    size_t len = 0;
    out[0] = '\0';
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        if (!(used & names[k].feature) || (modelled & names[k].feature))
            continue;
        if (names[k].feature == FEATURE_MANY_LIGHTS && !(modelled & FEATURE_LIGHTS))
            continue; /* "lights" already says it */
        int n = snprintf(out + len, out_size - len, "%s%s (chapter %s)", len ? ", " : "ignores: ", names[k].name,
                         names[k].chapter);
        if (n < 0 || (size_t)n >= out_size - len)
            break;
        len += (size_t)n;
    }
}
