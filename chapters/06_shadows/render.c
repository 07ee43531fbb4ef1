/* render.c - chapter 06's renderer: Lambertian shading with shadows.
 *
 * As chapter 05, and each shaded point casts a shadow ray towards the first
 * light: where a surface blocks the segment to the light, the point is
 * black.  --shadow-eps chooses where shadow rays start (spawn.h).
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps.
 * `render --acne-table` renders nothing: it prints the acne and leak
 * measurement (acne.h) of every policy at every scale, for this build.
 */
#include <stdio.h>
#include <string.h>

#include "05_lambert/shading_stage.h"
#include "06_shadows/acne.h"
#include "06_shadows/shade_shadows.h"

static spawn_knobs settings = SPAWN_KNOBS_DEFAULT;

static const knob knobs[] = {
    {"shadow-eps", KNOB_CHOICE, &settings.eps, eps_policy_names,
     "where secondary rays start: none (the blunder), fixed 1e-3, bound (error bound)"},
};

/* "build policy shape scale acne% leak%" a line, the build being this one's real type. */
static int acne_table(void)
{
    for (int p = 0; eps_policy_names[p]; p++) {
        for (int shape = 0; shape < ACNE_SHAPES; shape++) {
            for (int k = 0; k < ACNE_SCALES; k++) {
                acne_result result;
                if (acne_measure((acne_shape)shape, acne_scales[k], (eps_policy)p, 64, &result) != 0) {
                    fprintf(stderr, "06_shadows: out of memory\n");
                    return 1;
                }
                printf("%s %s %s %g %.2f %.2f\n", REAL_NAME, eps_policy_names[p], acne_shape_names[shape],
                       (double)acne_scales[k], result.acne, result.leak);
            }
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--acne-table") == 0)
        return acne_table();
    const shading_stage stage = {
        .name = "06_shadows",
        .summary = "06_shadows: Lambertian shading and shadow rays towards the first light\n"
                   "(render --acne-table prints the acne and leak measurement of each policy instead)",
        .knobs = knobs,
        .n_knobs = sizeof knobs / sizeof knobs[0],
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS,
        .shade = shade_shadows,
        .shade_knobs = &settings,
    };
    return shading_main(&stage, argc, argv);
}
