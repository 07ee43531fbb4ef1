/* render.c - chapter 06's renderer: Lambertian shading with shadows.
 *
 * As chapter 05, and each shaded point casts a shadow ray towards the first
 * light: where a surface blocks the segment to the light, the point is
 * black.  --shadow-eps chooses where shadow rays start (spawn.h).
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps.
 * The chapter's lab (lab/README.md) measures acne and leaks of each policy.
 */
#include "05_lambert/renderer/shading_stage.h"
#include "06_shadows/renderer/options.h"
#include "06_shadows/shade_shadows.h"

int main(int argc, char **argv)
{
    spawn_knobs settings = SPAWN_KNOBS_DEFAULT;
    knob rows[MAX_STAGE_KNOBS];
    stage_knobs aimed = {0};
    int n_rows = spawn_knob_rows(&settings, rows, &aimed);
    const shading_stage stage = {
        .name = "06_shadows",
        .summary = "06_shadows: Lambertian shading and shadow rays towards the first light",
        .knobs = rows,
        .n_knobs = n_rows,
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS,
        .shade = shade_shadows,
        .shade_knobs = aimed,
    };
    return shading_main(&stage, argc, argv);
}
