/* Boxes and the rounding a grid over them allows for: common/box.h. */
#include <math.h>

#include "box.h"
#include "suite.h"

/* min and max round nothing: every corner is one of the inputs, exactly. */
static void test_bounds_are_exact(void **state)
{
    (void)state;
    box s = box_of_sphere(vec3_make((real)0.1, -3, 1000), (real)-0.25); /* a negative radius counts as |radius| */
    assert_vec3_close(vec3_make((real)0.1 - (real)0.25, (real)-3.25, (real)999.75), s.lo, 0);
    assert_vec3_close(vec3_make((real)0.1 + (real)0.25, (real)-2.75, (real)1000.25), s.hi, 0);
    box t = box_of_triangle(vec3_make(1, -2, 3), vec3_make(-4, 5, (real)0.5), vec3_make(2, 0, -6));
    assert_vec3_close(vec3_make(-4, -2, -6), t.lo, 0);
    assert_vec3_close(vec3_make(2, 5, 3), t.hi, 0);
    box u = box_union(box_union(box_empty(), s), t); /* the empty box adds nothing */
    assert_vec3_close(vec3_make(-4, (real)-3.25, -6), u.lo, 0);
    assert_vec3_close(vec3_make(2, 5, (real)1000.25), u.hi, 0);
    box w = box_widen(t, (real)0.5);
    assert_vec3_close(vec3_make((real)-4.5, (real)-2.5, (real)-6.5), w.lo, 0);
    assert_vec3_close(vec3_make((real)2.5, (real)5.5, (real)3.5), w.hi, 0);
    assert_true(box_is_finite(u));
    assert_false(box_is_finite(box_empty()));
    assert_false(box_is_finite(box_of_sphere(vec3_make(0, (real)NAN, 0), 1)));
    assert_false(box_is_finite(box_of_triangle(vec3_make(0, 0, 0), vec3_make(REAL_INFINITY, 0, 0), vec3_make(0, 1, 0))));
}

/* The margin is 64 REAL_EPSILON times the largest coordinate (a power of two
 * times REAL_EPSILON: exact), and 1 for a box at the origin. */
static void test_margin(void **state)
{
    (void)state;
    box b = {vec3_make(-3, 1, 2), vec3_make(4, 1024, -512)};
    assert_close(64 * (double)REAL_EPSILON * 1024, box_margin(b), 0);
    b = (box){vec3_make(-2048, 1, 2), vec3_make(4, 5, 6)};
    assert_close(64 * (double)REAL_EPSILON * 2048, box_margin(b), 0);
    assert_close(1, box_margin((box){vec3_make(0, 0, 0), vec3_make(0, 0, 0)}), 0);
}

/* The conversion clamps first: NaN, infinities and reals far beyond an int. */
static void test_real_to_index(void **state)
{
    (void)state;
    assert_int_equal(3, real_to_index((real)3.99, 0, 9));
    assert_int_equal(0, real_to_index((real)-0.5, 0, 9)); /* clamped, not truncated towards 0 */
    assert_int_equal(0, real_to_index((real)-0.5, -1, 9)); /* within the range it truncates: floor first */
    assert_int_equal(-1, real_to_index(-7, -1, 9));
    assert_int_equal(9, real_to_index(9, 0, 9));
    assert_int_equal(9, real_to_index((real)1e30, 0, 9));
    assert_int_equal(0, real_to_index((real)-1e30, 0, 9));
    assert_int_equal(9, real_to_index(REAL_INFINITY, 0, 9));
    assert_int_equal(0, real_to_index((real)NAN, 0, 9));
}

/* inv_d and the slack: exact for powers of two; a zero (of either sign) or
 * a component whose reciprocal overflows gives 0 and no slack. */
static void test_ray_slack(void **state)
{
    (void)state;
    box b = {vec3_make(-8, 0, 0), vec3_make(2, 4, 4)};
    ray r = {vec3_make(1, -16, 2), vec3_make((real)0.25, -0.0, 2)};
    real inv_d[3], slack[3];
    real reach = box_ray_slack(b, r, inv_d, slack);
    const double want_reach = 16 * (double)REAL_EPSILON * (16 + 8);
    assert_close(want_reach, reach, 0);
    assert_close(4, inv_d[0], 0);
    assert_close(0, inv_d[1], 0);
    assert_close((real)0.5, inv_d[2], 0);
    assert_close(4 * want_reach, slack[0], 0);
    assert_close(0, slack[1], 0);
    assert_close(want_reach / 2, slack[2], 0);
    r.d = vec3_make(REAL_MIN / 8, 1, 0); /* 1 / d_x overflows */
    box_ray_slack(b, r, inv_d, slack);
    assert_close(0, inv_d[0], 0);
    assert_close(0, inv_d[2], 0);
    assert_close(1, inv_d[1], 0);
    assert_int_equal(2, (int)vec3_axis(vec3_make(0, 1, 2), 2));
}

static const graded_test tests[] = {
    GRADED(test_bounds_are_exact, 0),
    GRADED(test_margin, 0),
    GRADED(test_real_to_index, 0),
    GRADED(test_ray_slack, 0),
};
SUITE_MAIN("common_box", tests)
