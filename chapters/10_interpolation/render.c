/* render.c - chapter 10's renderer: interpolated normals and texture coordinates.
 *
 * The shading of chapters 05-09 at every point, with the mesh's interpolated
 * vertex normal as the shading normal and a textured shader's diffuse colour
 * read from its texture at the point's (u, v) (shade_interp.h).
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps
 * (chapter 06), --phong (chapter 07), --depth, --min-weight (chapter 08),
 * --fresnel (chapter 09), --normals=interpolated|geometric,
 * --texture-filter=nearest|bilinear, --below-surface=flip|keep.
 */
#include "05_lambert/renderer/shading_stage.h"
#include "10_interpolation/renderer/options.h"
#include "10_interpolation/scenes/interp_scene.h"
#include "10_interpolation/shade_interp.h"

int main(int argc, char **argv)
{
    interp_knobs settings = INTERP_KNOBS_DEFAULT;
    knob rows[MAX_STAGE_KNOBS];
    stage_knobs aimed = {0};
    int n_rows = interp_knob_rows(&settings, rows, &aimed);
    const shading_stage stage = {
        .name = "10_interpolation",
        .summary = "10_interpolation: interpolated vertex normals and texture coordinates, textures, over the "
                   "shading of chapters 05-09",
        .knobs = rows,
        .n_knobs = n_rows,
        .modelled = INTERP_MODELLED,
        .shade = shade_interp,
        .shade_knobs = aimed,
        .builtin = interp_scene,
    };
    return shading_main(&stage, argc, argv);
}
