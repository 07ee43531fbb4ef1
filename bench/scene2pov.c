/* scene2pov.c - a scene file (SCENES.md) as a POV-Ray 3.7 scene, for the bench.
 *
 *     scene2pov SCENE.xml OUT.pov [r|g|b]
 *
 * The translation renders the course's scenes as the course's solution does:
 * - radiance is displayed as (exposure L)^(1/2.2): the bench runs POV-Ray with
 *   File_Gamma=2.2 and no antialiasing, and the exposure scales every light
 *   and the background;
 * - a light's irradiance falls off as I / r^2.  POV-Ray's fade is
 *   2 / (1 + (r / D)^2) with fade_power 2; with the colour I / (2 D^2) the
 *   light gives I / (r^2 + D^2), which for D = 1e-4 is I / r^2 to 1e-8 / r^2;
 * - Lambertian: diffuse 1, no ambient, so L = k_d max(0, n.l) I / r^2;
 * - Phong: POV-Ray's `specular k roughness 1/p` is k (n.h)^p I / r^2, the
 *   course's half-vector term without the n.l factor.  POV-Ray's specular is
 *   one number: a shader whose specularColor is not grey is translated with
 *   the channel given as third argument (r, g or b), and the bench renders the
 *   scene three times and merges the channels (imgcmp merge);
 * - boxes are POV-Ray's analytic boxes, meshes mesh2 (smooth where the .obj
 *   has normals), triangles triangles;
 * - the camera is given by explicit direction, right and up vectors, which
 *   are the lecture's -w * projDistance, u * viewWidth and v * viewHeight.
 * Features POV-Ray would render differently (RGBNormals, textures, mirrors,
 * glass) are refused with a message: the comparison is for the scenes it
 * translates exactly.  Prints "grey" or "colour" (the specular colours).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"
#include "scene_build.h"

#define FADE_DISTANCE 1e-4

static int channel = -1; /* 0, 1, 2: translate a coloured specular for this channel */

static void put_vec(FILE *f, vec3 a) { fprintf(f, "<%.17g, %.17g, %.17g>", (double)a.x, (double)a.y, (double)a.z); }
static void put_rgb(FILE *f, color c, double scale)
{
    fprintf(f, "rgb <%.17g, %.17g, %.17g>", scale * (double)c.r, scale * (double)c.g, scale * (double)c.b);
}

static bool grey(color c) { return c.r == c.g && c.g == c.b; }

static double channel_of(color c)
{
    return channel == 1 ? (double)c.g : channel == 2 ? (double)c.b : (double)c.r;
}

static void put_texture(FILE *f, const scene *s, int shader)
{
    scene_shader sh = shader >= 0 ? s->shaders[shader] : scene_default_shader(SHADER_LAMBERTIAN);
    fprintf(f, "  texture { pigment { ");
    put_rgb(f, sh.diffuse_color, 1);
    fprintf(f, " } finish { ambient 0 emission 0 diffuse 1 brilliance 1 ");
    if (sh.kind == SHADER_PHONG) {
        double k = grey(sh.specular_color) ? (double)sh.specular_color.r : channel_of(sh.specular_color);
        fprintf(f, "specular %.17g roughness %.17g ", k, 1 / (double)sh.exponent);
    } else {
        fprintf(f, "specular 0 ");
    }
    fprintf(f, "phong 0 reflection { 0 } } }\n");
}

static void put_mesh(FILE *f, const mesh *m)
{
    bool smooth = m->n_normals > 0;
    for (int k = 0; k < m->n_faces && smooth; k++)
        for (int c = 0; c < 3; c++)
            smooth = smooth && m->faces[k].vn[c] >= 0;
    fprintf(f, "mesh2 {\n  vertex_vectors { %d", m->n_positions);
    for (int k = 0; k < m->n_positions; k++) {
        fprintf(f, ",\n    ");
        put_vec(f, m->positions[k]);
    }
    fprintf(f, " }\n");
    if (smooth) {
        fprintf(f, "  normal_vectors { %d", m->n_normals);
        for (int k = 0; k < m->n_normals; k++) {
            fprintf(f, ",\n    ");
            put_vec(f, m->normals[k]);
        }
        fprintf(f, " }\n");
    }
    fprintf(f, "  face_indices { %d", m->n_faces);
    for (int k = 0; k < m->n_faces; k++)
        fprintf(f, ",\n    <%d, %d, %d>", m->faces[k].v[0], m->faces[k].v[1], m->faces[k].v[2]);
    fprintf(f, " }\n");
    if (smooth) {
        fprintf(f, "  normal_indices { %d", m->n_faces);
        for (int k = 0; k < m->n_faces; k++)
            fprintf(f, ",\n    <%d, %d, %d>", m->faces[k].vn[0], m->faces[k].vn[1], m->faces[k].vn[2]);
        fprintf(f, " }\n");
    }
}

static int refuse(const char *path, const char *what)
{
    fprintf(stderr, "scene2pov: %s: %s has no exact POV-Ray translation\n", path, what);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 4 || (argc == 4 && (strlen(argv[3]) != 1 || !strchr("rgb", argv[3][0])))) {
        fprintf(stderr, "usage: scene2pov SCENE.xml OUT.pov [r|g|b]\n");
        return 2;
    }
    if (argc == 4)
        channel = (int)(strchr("rgb", argv[3][0]) - "rgb");
    scene s;
    char err[1024];
    if (scene_load(argv[1], &s, err, sizeof err) != 0) {
        fprintf(stderr, "scene2pov: %s\n", err);
        return 1;
    }
    int status = 0;
    bool coloured = false;
    for (int k = 0; k < s.n_shaders && !status; k++) {
        const scene_shader *sh = &s.shaders[k];
        if (sh->kind == SHADER_RGB_NORMALS)
            status = refuse(argv[1], "an RGBNormals shader");
        else if (sh->kind == SHADER_GLASS)
            status = refuse(argv[1], "a Glass shader");
        else if (sh->texture >= 0)
            status = refuse(argv[1], "a texture");
        else if (sh->mirror_coefficient.r != 0 || sh->mirror_coefficient.g != 0 || sh->mirror_coefficient.b != 0)
            status = refuse(argv[1], "a mirrorCoefficient");
        if (sh->kind == SHADER_PHONG && !grey(sh->specular_color))
            coloured = true;
    }
    if (!status && (s.ambient.r != 0 || s.ambient.g != 0 || s.ambient.b != 0))
        status = refuse(argv[1], "an ambient term");
    FILE *f = status ? NULL : fopen(argv[2], "w");
    if (!status && !f) {
        perror(argv[2]);
        status = 1;
    }
    if (status) {
        scene_free(&s);
        return status;
    }
    double exposure = (double)s.exposure;
    const scene_camera *c = &s.camera;
    vec3 w = vec3_normalize(vec3_neg(c->view_dir));
    vec3 u = vec3_normalize(vec3_cross(c->view_dir, c->view_up));
    vec3 v = vec3_cross(w, u);
    fprintf(f, "// %s, translated by bench/scene2pov%s\n", argv[1],
            channel >= 0 ? (channel == 0 ? " (red channel)" : channel == 1 ? " (green channel)" : " (blue channel)")
                         : "");
    fprintf(f, "#version 3.7;\nglobal_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 1 }\n");
    fprintf(f, "background { ");
    put_rgb(f, s.back_color, exposure);
    fprintf(f, " }\n");
    fprintf(f, "camera {\n  %s\n  location ", c->kind == CAMERA_ORTHOGRAPHIC ? "orthographic" : "perspective");
    put_vec(f, c->view_point);
    fprintf(f, "\n  direction ");
    put_vec(f, vec3_scale(vec3_neg(w), c->kind == CAMERA_ORTHOGRAPHIC ? 1 : c->proj_distance));
    fprintf(f, "\n  right ");
    put_vec(f, vec3_scale(u, c->view_width));
    fprintf(f, "\n  up ");
    put_vec(f, vec3_scale(v, c->view_height));
    fprintf(f, "\n}\n");
    for (int k = 0; k < s.n_lights; k++) {
        fprintf(f, "light_source { ");
        put_vec(f, s.lights[k].position);
        fprintf(f, " ");
        put_rgb(f, s.lights[k].intensity, exposure / (2 * FADE_DISTANCE * FADE_DISTANCE));
        fprintf(f, " fade_distance %g fade_power 2 }\n", FADE_DISTANCE);
    }
    for (int k = 0; k < s.n_surfaces; k++) {
        const scene_surface *sf = &s.surfaces[k];
        switch (sf->kind) {
        case SURFACE_SPHERE:
            fprintf(f, "sphere { ");
            put_vec(f, sf->center);
            fprintf(f, ", %.17g\n", (double)sf->radius);
            break;
        case SURFACE_BOX:
            fprintf(f, "box { ");
            put_vec(f, sf->min_pt);
            fprintf(f, ", ");
            put_vec(f, sf->max_pt);
            fprintf(f, "\n");
            break;
        case SURFACE_TRIANGLE:
            fprintf(f, "triangle { ");
            put_vec(f, sf->v0);
            fprintf(f, ", ");
            put_vec(f, sf->v1);
            fprintf(f, ", ");
            put_vec(f, sf->v2);
            fprintf(f, "\n");
            break;
        case SURFACE_MESH:
            put_mesh(f, &s.meshes[sf->mesh]);
            break;
        }
        put_texture(f, &s, sf->shader);
        fprintf(f, "}\n");
    }
    if (fclose(f) != 0) {
        perror(argv[2]);
        status = 1;
    }
    if (!status)
        printf("%s\n", coloured ? "colour" : "grey");
    scene_free(&s);
    return status;
}
