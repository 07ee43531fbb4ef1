/* render.c - chapter 05's renderer: point lights and Lambertian shading.
 *
 * Each eye ray's closest hit is shaded with the Lambert term of the scene's
 * first light, L_d = k_d max(0, n . l) I / r^2 (lambert.h), with the shading
 * normal turned towards the viewer.  No shadows yet (chapter 06): a light
 * shines through everything between it and the point.
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03).
 */
#include "05_lambert/shade_lambert.h"
#include "05_lambert/renderer/shading_stage.h"

int main(int argc, char **argv)
{
    const shading_stage stage = {
        .name = "05_lambert",
        .summary = "05_lambert: point lights and Lambertian shading, L_d = k_d max(0, n.l) I / r^2 (no shadows)",
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS,
        .shade = shade_lambert,
    };
    return shading_main(&stage, argc, argv);
}
