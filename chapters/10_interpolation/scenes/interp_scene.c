/* interp_scene.c - chapter 10: the built-in scene of the interpolation stage. */
#include "10_interpolation/scenes/interp_scene.h"

#include <stdlib.h>

#include "10_interpolation/scenes/sphere_mesh.h"
#include "scene_build.h"

/* The floor: the square |x|, |z| <= half at height y, two triangles facing
 * up, texture coordinates from -1 to 4 along x and z. */
static int floor_mesh(mesh *m, real half, real y)
{
    *m = (mesh){.n_positions = 4, .n_uvs = 4, .n_faces = 2};
    m->positions = malloc(sizeof *m->positions * 4);
    m->uvs = malloc(sizeof *m->uvs * 4);
    m->faces = malloc(sizeof *m->faces * 2);
    if (!m->positions || !m->uvs || !m->faces) {
        mesh_free(m);
        return -1;
    }
    const real corner[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}}; /* (x, z) signs, counter-clockwise from above */
    for (int k = 0; k < 4; k++) {
        m->positions[k] = vec3_make(corner[k][0] * half, y, corner[k][1] * half);
        m->uvs[k] = (mesh_uv){corner[k][0] < 0 ? -1 : 4, corner[k][1] > 0 ? -1 : 4};
    }
    m->faces[0] = (mesh_face){{0, 1, 2}, {0, 1, 2}, {-1, -1, -1}};
    m->faces[1] = (mesh_face){{0, 2, 3}, {0, 2, 3}, {-1, -1, -1}};
    return 0;
}

/* Adds mesh m (taken over) as a surface with `shader`; -1 when out of memory. */
static int add_mesh(scene *desc, mesh m, int shader)
{
    int k = scene_add_mesh(desc, m);
    if (k < 0) {
        mesh_free(&m);
        return -1;
    }
    return scene_add_surface(desc, (scene_surface){.kind = SURFACE_MESH, .shader = shader, .mesh = k}) < 0 ? -1 : 0;
}

static int add_sphere(scene *desc, vec3 center, bool normals, int shader)
{
    mesh m;
    if (sphere_mesh(&m, center, 1, INTERP_SCENE_SEGMENTS, INTERP_SCENE_BANDS, normals) != 0)
        return -1;
    return add_mesh(desc, m, shader);
}

int interp_scene(scene *desc)
{
    desc->has_camera = true;
    desc->camera = (scene_camera){
        .kind = CAMERA_PERSPECTIVE,
        .view_point = {0, 1.9, 7},
        .view_dir = {0, -2.4, -7},
        .view_up = {0, 1, 0},
        .proj_distance = 2,
        .view_width = 2.1,
        .view_height = 2.1,
    };
    desc->back_color = color_make((real)0.25, (real)0.3, (real)0.4);
    desc->ambient = color_make((real)0.02, (real)0.02, (real)0.02);
    texture_image globe;
    if (globe_texture(&globe, 128, 64, 8) != 0)
        return -1;
    int texture = scene_add_texture(desc, (scene_texture){.kind = TEXTURE_REPEAT, .image = globe});
    if (texture < 0) {
        texture_image_free(&globe);
        return -1;
    }
    scene_shader textured = scene_default_shader(SHADER_PHONG);
    textured.texture = texture; /* the texture replaces diffuseColor */
    textured.specular_color = color_make((real)0.3, (real)0.3, (real)0.3);
    textured.exponent = 40;
    scene_shader mirror = scene_default_shader(SHADER_PHONG);
    mirror.diffuse_color = color_make((real)0.02, (real)0.02, (real)0.02);
    mirror.specular_color = color_make((real)0.5, (real)0.5, (real)0.5);
    mirror.exponent = 200;
    mirror.mirror_coefficient = color_make((real)0.85, (real)0.85, (real)0.85);
    scene_shader tiles = scene_default_shader(SHADER_LAMBERTIAN);
    tiles.texture = texture;
    int globe_shader = scene_add_shader(desc, textured), mirror_shader = scene_add_shader(desc, mirror),
        floor_shader = scene_add_shader(desc, tiles);
    mesh floor;
    if (globe_shader < 0 || mirror_shader < 0 || floor_shader < 0 || floor_mesh(&floor, 6, -1) != 0)
        return -1;
    if (add_mesh(desc, floor, floor_shader) != 0 ||
        add_sphere(desc, vec3_make((real)-2.3, 0, 0), false, globe_shader) != 0 || /* geometric normals */
        add_sphere(desc, vec3_make(0, 0, 0), true, globe_shader) != 0 ||           /* interpolated normals */
        add_sphere(desc, vec3_make((real)2.3, 0, 0), true, mirror_shader) != 0)    /* a coarse mirror */
        return -1;
    /* The key light high on the right, a weaker fill light low on the left. */
    if (scene_add_light(desc, (scene_light){.position = {4, 8, 6}, .intensity = {60, 60, 60}}) < 0 ||
        scene_add_light(desc, (scene_light){.position = {-7, 2, 4}, .intensity = {12, 12, 15}}) < 0)
        return -1;
    return 0;
}
