/* A shading normal on the viewer's side of the surface (common/shading_side.h):
 * n_s, or -n_s when n_s . n_g < 0; the mirror direction kept above it is
 * tested with chapter 10's shading (tests/test_10_interpolation.c). */
#include "shading_side.h"
#include "suite.h"

/* Negation is exact: the side is decided by the sign of n_s . n_g alone,
 * and a perpendicular n_s (n_s . n_g = 0) is kept as it is. */
static void test_side_of_geometric_normal(void **state)
{
    (void)state;
    vec3 n_s = vec3_make((real)0.6, 0, (real)0.8); /* unit: 0.36 + 0.64 */
    assert_vec3_close(n_s, shading_normal(n_s, vec3_make(0, 0, 1)), 0);
    assert_vec3_close(vec3_make((real)-0.6, 0, (real)-0.8), shading_normal(n_s, vec3_make(0, 0, -1)), 0);
    assert_vec3_close(n_s, shading_normal(n_s, vec3_make((real)0.8, 0, (real)-0.6)), 0); /* dot 0.48 - 0.48 */
    assert_vec3_close(vec3_make((real)-0.6, 0, (real)-0.8), shading_normal(n_s, vec3_make(-1, 0, 0)), 0);
}

/* About n_s = n_g the mirror direction of any v above is above: n_s kept.
 * Tilted so that r goes below, the result is normalize(v + r'), worked by
 * hand: n_g = z, v = (0.6, 0, 0.8), n_s = (-0.6, 0, 0.8) gives r = 2 (0.28)
 * n_s - v = (-0.936, 0, -0.352), r' = (-0.936, 0, 0.352), v + r' = (-0.336,
 * 0, 1.152), |v + r'| = 1.2: n' = (-0.28, 0, 0.96).  A few roundings of
 * values of size 1. */
static void test_mirror_above_by_hand(void **state)
{
    (void)state;
    vec3 z = vec3_make(0, 0, 1), v = vec3_make((real)0.6, 0, (real)0.8);
    assert_vec3_close(z, mirror_above(z, z, v), 0);
    assert_vec3_close(vec3_make((real)-0.28, 0, (real)0.96), mirror_above(vec3_make((real)-0.6, 0, (real)0.8), z, v),
                      16 * REAL_EPSILON);
}

static const graded_test tests[] = {
    GRADED(test_side_of_geometric_normal, 0),
    GRADED(test_mirror_above_by_hand, 0),
};
SUITE_MAIN("common_shading_side", tests)
