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
#include "05_lambert/renderer/shading_stage.h"
#include "09_refraction/renderer/options.h"
#include "09_refraction/scenes/glass_scene.h"
#include "09_refraction/shade_glass.h"

int main(int argc, char **argv)
{
    glass_knobs settings = GLASS_KNOBS_DEFAULT;
    knob rows[MAX_STAGE_KNOBS];
    stage_knobs aimed = {0};
    int n_rows = glass_knob_rows(&settings, rows, &aimed);
    const shading_stage stage = {
        .name = "09_refraction",
        .summary = "09_refraction: glass (Snell's law, total internal reflection, Fresnel) over chapter 08's mirrors",
        .knobs = rows,
        .n_knobs = n_rows,
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS | FEATURE_MANY_LIGHTS |
                    FEATURE_PHONG | FEATURE_AMBIENT | FEATURE_MIRRORS | FEATURE_GLASS,
        .shade = shade_glass,
        .shade_knobs = aimed,
        .builtin = glass_scene,
    };
    return shading_main(&stage, argc, argv);
}
