/* Fuzz target: the scene reader (common/scene.h), with the meshes and
 * textures it loads.  Contracts: a scene that loads holds only indices in
 * range, finite numbers, sorted box corners, positive radii and decoded
 * textures; a scene that fails to load is left empty and its message starts
 * with "path:line: " naming a line of the file. */
#include <math.h>
#include <string.h>

#include "fuzz.h"
#include "scene.h"

static bool finite3(vec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

static void check_mesh(const mesh *m)
{
    fuzz_check(m->n_faces > 0, "a mesh without faces was accepted");
    for (int k = 0; k < m->n_positions; k++)
        fuzz_check(finite3(m->positions[k]), "mesh position %d is not finite", k);
    for (int k = 0; k < m->n_faces; k++) {
        for (int c = 0; c < 3; c++) {
            const mesh_face *f = &m->faces[k];
            fuzz_check(f->v[c] >= 0 && f->v[c] < m->n_positions, "face %d: vertex index %d", k, f->v[c]);
            fuzz_check(f->vt[c] >= -1 && f->vt[c] < m->n_uvs, "face %d: uv index %d", k, f->vt[c]);
            fuzz_check(f->vn[c] >= -1 && f->vn[c] < m->n_normals, "face %d: normal index %d", k, f->vn[c]);
        }
    }
}

static void check_loaded(const scene *s)
{
    fuzz_check(s->width >= 0 && s->width <= SCENE_MAX_IMAGE_SIDE && s->height >= 0 &&
                   s->height <= SCENE_MAX_IMAGE_SIDE && (s->width == 0) == (s->height == 0),
               "image size %d x %d", s->width, s->height);
    fuzz_check(s->samples >= 0 && s->samples <= 65536, "samples %d", s->samples);
    fuzz_check(isfinite(s->exposure) && s->exposure > 0, "exposure %g", (double)s->exposure);
    const scene_camera *c = &s->camera;
    fuzz_check(finite3(c->view_point) && finite3(c->view_dir) && finite3(c->view_up) && isfinite(c->proj_distance) &&
                   isfinite(c->view_width) && isfinite(c->view_height),
               "a camera value is not finite");
    for (int k = 0; k < s->n_textures; k++) {
        const texture_image *t = &s->textures[k].image;
        fuzz_check(t->rgb && t->width >= 1 && t->height >= 1 && t->width <= TEXTURE_MAX_SIDE &&
                       t->height <= TEXTURE_MAX_SIDE,
                   "texture %d: %d x %d texels", k, t->width, t->height);
        color last = texture_image_texel(t, t->width - 1, t->height - 1); /* in bounds, for ASan */
        fuzz_check(last.r >= 0 && last.r <= 1, "texel out of [0, 1]");
    }
    for (int k = 0; k < s->n_shaders; k++) {
        const scene_shader *sh = &s->shaders[k];
        fuzz_check(sh->texture >= -1 && sh->texture < s->n_textures, "shader %d: texture %d", k, sh->texture);
        fuzz_check(sh->diffuse_color.r >= 0 && sh->specular_color.g >= 0 && sh->mirror_coefficient.b >= 0 &&
                       sh->exponent >= 0 && sh->refractive_index > 0,
                   "shader %d: a value out of its range", k);
    }
    for (int k = 0; k < s->n_surfaces; k++) {
        const scene_surface *f = &s->surfaces[k];
        fuzz_check(f->shader >= -1 && f->shader < s->n_shaders, "surface %d: shader %d", k, f->shader);
        fuzz_check(f->line >= 1, "surface %d: line %d", k, f->line);
        switch (f->kind) {
        case SURFACE_SPHERE:
            fuzz_check(f->radius > 0 && isfinite(f->radius) && finite3(f->center), "sphere %d", k);
            break;
        case SURFACE_BOX:
            fuzz_check(f->min_pt.x <= f->max_pt.x && f->min_pt.y <= f->max_pt.y && f->min_pt.z <= f->max_pt.z,
                       "box %d: corners not sorted", k);
            break;
        case SURFACE_MESH:
            fuzz_check(f->mesh >= 0 && f->mesh < s->n_meshes, "surface %d: mesh %d", k, f->mesh);
            break;
        case SURFACE_TRIANGLE:
            fuzz_check(finite3(f->v0) && finite3(f->v1) && finite3(f->v2), "triangle %d", k);
            break;
        }
    }
    for (int k = 0; k < s->n_meshes; k++)
        check_mesh(&s->meshes[k]);
    for (int k = 0; k < s->n_lights; k++)
        fuzz_check(s->lights[k].intensity.r >= 0 && finite3(s->lights[k].position), "light %d", k);
}

int fuzz_scene(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("scene.xml", data, size);
    scene s;
    char err[1024] = "";
    if (scene_load(path, &s, err, sizeof err) == 0) {
        fuzz_check(err[0] == '\0', "a loaded scene left a message: %s", err);
        check_loaded(&s);
        scene_free(&s);
        return 0;
    }
    fuzz_check(s.n_surfaces == 0 && s.n_shaders == 0 && s.n_textures == 0 && s.n_lights == 0 && s.n_meshes == 0 &&
                   !s.surfaces && !s.shaders && !s.textures && !s.lights && !s.meshes && !s.path,
               "a failed load left something in the scene");
    /* expat counts a line after the last newline too */
    fuzz_check(fuzz_names_line(err, path, fuzz_count_lines(data, size, true) + 1), "message without path:line: '%s'",
               err);
    return 0;
}

FUZZ_ENTRY(fuzz_scene)
