/* seeded_scene.h - a scene drawn at grading time, traced by a shading
 * chapter's stage (tests/answers.h; chapters 06 on).
 *
 * A handful of spheres and triangles about the origin (size 10), a large
 * floor below them, one to three lights, and shaders of the kinds asked
 * for; eye rays from a ring around it aimed at its surfaces.  The radiance
 * of each ray is an answer.  Chapters 01-05 are the reference's in both
 * runs, so where rays meet surfaces is the same to the last bit; the
 * student's shading differs from the reference's by the roundings of a
 * correct formula, amplified by at most the Phong exponent (up to 50) and
 * by the bounces of mirrors and glass: 4096 REAL_EPSILON of the radiance
 * (plus one of the brightest light's) leaves room.  A ray that passes a
 * silhouette or a shadow's edge within that margin is as likely as the
 * margin is small.
 */
#ifndef RT_TESTS_SEEDED_SCENE_H
#define RT_TESTS_SEEDED_SCENE_H

#include "seeded.h"
#include "shading_suite.h"

typedef struct {
    int phong;  /* Phong shaders (specular colour, exponent) */
    int mirror; /* some shaders with a mirror coefficient */
    int glass;  /* some Glass shaders */
} seeded_materials;

/* desc (initialized here; free it) drawn from rng with the materials m. */
static inline void seeded_scene(unsigned long *rng, scene *desc, seeded_materials m)
{
    scene_init(desc);
    desc->back_color = seeded_color(rng, 0, 0.3);
    int n_shaders = 4;
    for (int k = 0; k < n_shaders; k++) {
        scene_shader s = scene_default_shader(m.phong && k % 2 ? SHADER_PHONG : SHADER_LAMBERTIAN);
        s.diffuse_color = seeded_color(rng, 0.05, 0.8);
        s.specular_color = seeded_color(rng, 0, 0.6);
        s.exponent = (real)seeded_between(rng, 1, 50);
        if (m.mirror && k >= 2)
            s.mirror_coefficient = seeded_color(rng, 0.1, 0.8);
        if (m.glass && k == 3) {
            s.kind = SHADER_GLASS;
            s.refractive_index = (real)seeded_between(rng, 1.1, 2);
        }
        scene_add_shader(desc, s);
    }
    suite_add_floor(desc, 0, vec3_make(0, -12, 0));
    int n = 3 + (int)seeded_between(rng, 0, 5);
    for (int k = 0; k < n; k++) {
        int shader = (int)seeded_between(rng, 0, n_shaders);
        vec3 c = seeded_point(rng, 8);
        if (k % 2) {
            vec3 v1 = vec3_add(c, seeded_point(rng, 4)), v2 = vec3_add(c, seeded_point(rng, 4));
            scene_add_surface(desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = shader, .v0 = c, .v1 = v1,
                                                    .v2 = v2});
        } else {
            scene_add_surface(desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = shader, .center = c,
                                                    .radius = (real)seeded_between(rng, 0.5, 3)});
        }
    }
    int lights = 1 + (int)seeded_between(rng, 0, 3);
    for (int k = 0; k < lights; k++) {
        vec3 p = vec3_add(seeded_point(rng, 12), vec3_make(0, 14, 0));
        scene_add_light(desc, (scene_light){.position = p, .intensity = seeded_color(rng, 50, 300)});
    }
}

/* The radiance of `count` eye rays through desc, traced with shade and
 * knobs, as answers named after `what`; with the rays cast of each kind. */
static inline void seeded_trace_answers(unsigned long *rng, const scene *desc, shade_fn shade, const stage_knobs *knobs,
                                        const char *what, int count)
{
    shading_view *view = suite_view(desc, shade, knobs);
    for (int k = 0; k < count; k++) {
        double angle = seeded_between(rng, 0, 2 * acos(-1.0));
        vec3 eye = vec3_make((real)(30 * cos(angle)), (real)seeded_between(rng, -5, 15), (real)(30 * sin(angle)));
        vec3 target = desc->n_surfaces > 1 ? seeded_point(rng, 8) : vec3_make(0, 0, 0);
        uint64_t rays[RAY_KINDS] = {0};
        color L = trace(&view->tr, (ray){eye, vec3_sub(target, eye)}, 0, REAL_INFINITY, 0, rays);
        double size = 1 + fmax(L.r, fmax(L.g, L.b));
        const char *in = describe("%s, ray %d", what, k + 1);
        suite_answer_rgb(describe("%s: radiance", in), L, 4096 * REAL_EPSILON * size);
        for (int kind = 0; kind < RAY_KINDS; kind++)
            suite_answer(describe("%s: rays of kind %d", in, kind), (double)rays[kind], 0);
    }
    shading_release(view);
}

/* Three scenes drawn from rng with the materials m, each traced by eight
 * eye rays with shade and knobs (named after `what`). */
static inline void seeded_scenes(unsigned long *rng, seeded_materials m, shade_fn shade, const stage_knobs *knobs,
                                 const char *what)
{
    for (int n = 0; n < 3; n++) {
        scene desc;
        seeded_scene(rng, &desc, m);
        seeded_trace_answers(rng, &desc, shade, knobs, describe("%s, scene %d", what, n + 1), 8);
        scene_free(&desc);
    }
}

#endif
