/* render.c - chapter 07's renderer: Blinn-Phong shading, ambient light, every light.
 *
 * Each shaded point gets the scene's ambient radiance plus, for each light
 * whose shadow ray is not blocked, the Lambert term and, for a Phong shader,
 * the specular term k_s max(0, n . h)^p I / r^2 (phong.h).
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps
 * (chapter 06), --phong=course|lecture (is the specular term multiplied by
 * max(0, n . l)?  The course's images: no).
 */
#include "05_lambert/renderer/shading_stage.h"
#include "07_blinn_phong/renderer/options.h"
#include "07_blinn_phong/shade_phong.h"

int main(int argc, char **argv)
{
    phong_knobs settings = PHONG_KNOBS_DEFAULT;
    knob rows[MAX_STAGE_KNOBS];
    stage_knobs aimed = {0};
    int n_rows = phong_knob_rows(&settings, rows, &aimed);
    const shading_stage stage = {
        .name = "07_blinn_phong",
        .summary = "07_blinn_phong: Blinn-Phong shading, ambient light and every light of the scene, with shadows",
        .knobs = rows,
        .n_knobs = n_rows,
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS | FEATURE_MANY_LIGHTS |
                    FEATURE_PHONG | FEATURE_AMBIENT,
        .shade = shade_phong,
        .shade_knobs = aimed,
    };
    return shading_main(&stage, argc, argv);
}
