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
#include "05_lambert/renderer/shading_stage.h"
#include "08_mirrors/renderer/options.h"
#include "08_mirrors/scenes/mirror_scene.h"
#include "08_mirrors/shade_glazed.h"

int main(int argc, char **argv)
{
    path_knobs settings = PATH_KNOBS_DEFAULT;
    knob rows[MAX_STAGE_KNOBS];
    stage_knobs aimed = {0};
    int n_rows = path_knob_rows(&settings, rows, &aimed);
    const shading_stage stage = {
        .name = "08_mirrors",
        .summary = "08_mirrors: Blinn-Phong shading plus k_m times the radiance traced along the mirror direction",
        .knobs = rows,
        .n_knobs = n_rows,
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS | FEATURE_MANY_LIGHTS |
                    FEATURE_PHONG | FEATURE_AMBIENT | FEATURE_MIRRORS,
        .shade = shade_glazed,
        .shade_knobs = aimed,
        .builtin = mirror_scene,
    };
    return shading_main(&stage, argc, argv);
}
