/* render.c - chapter 10's renderer: interpolated normals and texture coordinates.
 *
 * The shading of chapters 05-09 at every point, with the mesh's interpolated
 * vertex normal as the shading normal and a textured shader's diffuse colour
 * read from its texture at the point's (u, v) (shade_interp.h).
 *
 * Knobs: --sphere (chapter 02), --triangle (chapter 03), --shadow-eps
 * (chapter 06), --phong (chapter 07), --depth, --min-weight (chapter 08),
 * --texture-filter=nearest|bilinear, --below-surface=flip|keep.
 */
#include "10_interpolation/interp_stage.h"

int main(int argc, char **argv)
{
    interp_knobs settings = INTERP_KNOBS_DEFAULT;
    knob rows[MAX_STAGE_KNOBS];
    const shading_stage stage = interp_stage(&settings, rows, NULL);
    return shading_main(&stage, argc, argv);
}
