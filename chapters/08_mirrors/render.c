/* render.c - chapter 08's renderer: mirrors, by recursion.
 *
 * Each shaded point gets chapter 07's shading (ambient, every unblocked
 * light, Blinn-Phong highlights) and, where its shader has a mirror
 * coefficient k_m, k_m times the radiance traced along the mirror direction
 * (shade_glazed.h), one level deeper, until --depth or --min-weight stops it.
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps
 * (chapter 06, for mirror rays too), --phong (chapter 07), --depth,
 * --min-weight.  The chapter's lab (lab/README.md) measures how often a
 * convex mirror sees itself under each policy.
 */
#include "05_lambert/shading_stage.h"
#include "08_mirrors/scenes/mirror_scene.h"
#include "08_mirrors/shade_glazed.h"

static path_knobs settings = PATH_KNOBS_DEFAULT;

static const knob knobs[] = {
    {"shadow-eps", KNOB_CHOICE, &settings.phong.spawn.eps, eps_policy_names,
     "where secondary rays (shadow, mirror) start: none (the blunder), fixed 1e-3, bound (error bound)"},
    {"phong", KNOB_CHOICE, &settings.phong.form, phong_form_names,
     "specular term: course k_s (n.h)^p I/r^2, lecture also times max(0, n.l)"},
    {"depth", KNOB_INT, &settings.depth, NULL, "deepest bounce traced (0: eye rays only; at most 256)"},
    {"min-weight", KNOB_REAL, &settings.min_weight, NULL,
     "no ray whose path weight (product of k_m along it) is below this (0: off)"},
};

int main(int argc, char **argv)
{
    const shading_stage stage = {
        .name = "08_mirrors",
        .summary = "08_mirrors: Blinn-Phong shading plus k_m times the radiance traced along the mirror direction",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS | FEATURE_MANY_LIGHTS |
                    FEATURE_PHONG | FEATURE_AMBIENT | FEATURE_MIRRORS,
        .shade = shade_glazed,
        .shade_knobs = &settings,
        .builtin = mirror_scene,
    };
    return shading_main(&stage, argc, argv);
}
