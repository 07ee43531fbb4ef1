/* render.c - chapter 03's renderer: triangles, coloured by where the ray hits them.
 *
 * Each pixel's colour is (alpha, beta, gamma) of the closest hit as RGB:
 * each vertex is a pure red, green or blue, each edge a mix of two
 * (triangle_stage.h).  --triangle chooses the test: cramer (the lecture's)
 * or watertight.  The built-in scene is one large triangle and an
 * icosahedron.  A scene file's Triangle surfaces are rendered; spheres,
 * boxes and meshes are left to chapter 04, which puts every shape into one
 * list.  The chapter's lab (lab/README.md) measures the cracks between
 * triangles and the hits at degenerate ones.
 */
#include "03_triangle/triangle_stage.h"

int main(int argc, char **argv)
{
    int test = TRIANGLE_CRAMER; /* --triangle */
    knob row;
    const renderer r = triangle_stage_renderer(&test, &row);
    return renderer_main(&r, argc, argv);
}
