/* render.c - chapter 08's renderer: mirrors, by recursion.
 *
 * Each shaded point gets chapter 07's shading (ambient, every unblocked
 * light, Blinn-Phong highlights) and, where its shader has a mirror
 * coefficient k_m, k_m times the radiance traced along the mirror direction
 * (shade_glazed.h), one level deeper, until --depth or --min-weight stops it.
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps
 * (chapter 06, for mirror rays too), --phong (chapter 07), --depth,
 * --min-weight.
 * `render --self-hit-table` renders nothing: it prints the self-hit
 * measurement of a convex mirror (self_hit.h) for every policy and scale.
 */
#include <stdio.h>
#include <string.h>

#include "05_lambert/shading_stage.h"
#include "08_mirrors/mirror_scene.h"
#include "08_mirrors/self_hit.h"
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

/* "build policy scale band_start rays hits" a line. */
static int self_hit_table(void)
{
    printf("# build policy scale theta_i_from rays hits (a convex mirror seeing itself, self_hit.h)\n");
    for (int p = 0; eps_policy_names[p]; p++)
        for (int k = 0; k < SELF_HIT_SCALES; k++) {
            self_hit_result result;
            self_hit_measure(self_hit_scales[k], (eps_policy)p, 20000, &result);
            for (int b = 0; b < SELF_HIT_BANDS; b++)
                printf("%s %s %g %g %ld %ld\n", REAL_NAME, eps_policy_names[p], (double)self_hit_scales[k],
                       self_hit_band_start[b], result.rays[b], result.hits[b]);
        }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--self-hit-table") == 0)
        return self_hit_table();
    const shading_stage stage = {
        .name = "08_mirrors",
        .summary = "08_mirrors: Blinn-Phong shading plus k_m times the radiance traced along the mirror direction\n"
                   "(render --self-hit-table prints how often a convex mirror sees itself, by policy, instead)",
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
