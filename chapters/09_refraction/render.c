/* render.c - chapter 09's renderer: glass, by Snell's law and Fresnel's equations.
 *
 * A Glass shader reflects R and transmits 1 - R of what it sees, each traced
 * one level deeper (shade_glass.h); every other shader is chapter 08's
 * glazed surface.
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps
 * (chapter 06, for every secondary ray), --phong (chapter 07), --depth,
 * --min-weight (chapter 08), --fresnel=exact|schlick.
 * `render --fresnel-table` renders nothing: it prints R against the angle
 * (fresnel.h) for eta = 1.5, both ways, for the plot of the README;
 * `render --limits` prints where the build's precision gives out
 * (glass_limits.h).
 */
#include <stdio.h>
#include <string.h>

#include "05_lambert/shading_stage.h"
#include "09_refraction/fresnel_table.h"
#include "09_refraction/glass_limits.h"
#include "09_refraction/glass_scene.h"
#include "09_refraction/shade_glass.h"

static glass_knobs settings = GLASS_KNOBS_DEFAULT;

static const knob knobs[] = {
    {"shadow-eps", KNOB_CHOICE, &settings.path.phong.spawn.eps, eps_policy_names,
     "where secondary rays start: none (the blunder), fixed 1e-3, bound (error bound)"},
    {"phong", KNOB_CHOICE, &settings.path.phong.form, phong_form_names,
     "specular term: course k_s (n.h)^p I/r^2, lecture also times max(0, n.l)"},
    {"depth", KNOB_INT, &settings.path.depth, NULL, "deepest bounce traced (0: eye rays only; at most 256)"},
    {"min-weight", KNOB_REAL, &settings.path.min_weight, NULL,
     "no ray whose path weight (product of k_m, R, 1 - R along it) is below this (0: off)"},
    {"fresnel", KNOB_CHOICE, &settings.fresnel, fresnel_mode_names,
     "glass reflectance: exact (Fresnel's equations) or schlick (Schlick's approximation)"},
};

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--fresnel-table") == 0)
        return fresnel_table(stdout, (real)1.5, 90 * 8);
    if (argc == 2 && strcmp(argv[1], "--limits") == 0) {
        glass_limits(stdout);
        return 0;
    }
    const shading_stage stage = {
        .name = "09_refraction",
        .summary = "09_refraction: glass (Snell's law, total internal reflection, Fresnel) over chapter 08's mirrors\n"
                   "(render --fresnel-table prints R against the angle for eta 1.5 instead,\n"
                   "render --limits where the build's precision gives out)",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS | FEATURE_MANY_LIGHTS |
                    FEATURE_PHONG | FEATURE_AMBIENT | FEATURE_MIRRORS | FEATURE_GLASS,
        .shade = shade_glass,
        .shade_knobs = &settings,
        .builtin = glass_scene,
    };
    return shading_main(&stage, argc, argv);
}
