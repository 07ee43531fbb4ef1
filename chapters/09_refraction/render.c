/* render.c - chapter 09's renderer: glass, by Snell's law and Fresnel's equations.
 *
 * A Glass shader reflects R and transmits 1 - R of what it sees, each traced
 * one level deeper (shade_glass.h); every other shader is chapter 08's
 * glazed surface.
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps
 * (chapter 06, for every secondary ray), --phong (chapter 07), --depth,
 * --min-weight (chapter 08), --fresnel=exact|schlick.  The chapter's lab
 * (lab/README.md) prints R against the angle and where the precision gives
 * out.
 */
#include "05_lambert/shading_stage.h"
#include "09_refraction/scenes/glass_scene.h"
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
    const shading_stage stage = {
        .name = "09_refraction",
        .summary = "09_refraction: glass (Snell's law, total internal reflection, Fresnel) over chapter 08's mirrors",
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
