/* Texture coordinates in texel units (common/texture_space.h): s n, held
 * within +-2^40, NaN as 0. */
#include <math.h>

#include "suite.h"
#include "texture_space.h"

#define TWO_TO_40 ((real)1099511627776.0)

/* Products whose factors and result are exact in binary come out exactly. */
static void test_exact_products(void **state)
{
    (void)state;
    assert_true(texel_coordinate((real)0.25, 8) == 2);
    assert_true(texel_coordinate((real)-0.5, 6) == -3);
    assert_true(texel_coordinate(1, 128) == 128);
    assert_true(texel_coordinate(0, 64) == 0);
}

/* 0.1 n is one rounded product of size n: within half an ulp of n, less
 * than n REAL_EPSILON. */
static void test_rounded_product(void **state)
{
    (void)state;
    assert_close(10, texel_coordinate((real)0.1, 100), 100 * REAL_EPSILON);
    assert_close(76.8, texel_coordinate((real)0.6, 128), 128 * REAL_EPSILON);
}

/* Beyond 2^40 texels the coordinate is held at +-2^40 (exact in both
 * builds), infinities too; NaN reads 0. */
static void test_limits(void **state)
{
    (void)state;
    assert_true(texel_coordinate((real)1e30, 16) == TWO_TO_40);
    assert_true(texel_coordinate((real)-1e30, 16) == -TWO_TO_40);
    assert_true(texel_coordinate((real)INFINITY, 3) == TWO_TO_40);
    assert_true(texel_coordinate((real)-INFINITY, 3) == -TWO_TO_40);
    assert_true(texel_coordinate((real)NAN, 5) == 0);
    /* just inside the limit, the product is kept: 2^39 = 2^36 8 */
    assert_true(texel_coordinate((real)68719476736.0, 8) == TWO_TO_40 / 2);
}

static const graded_test tests[] = {
    GRADED(test_exact_products, 0),
    GRADED(test_rounded_product, 0),
    GRADED(test_limits, 0),
};
SUITE_MAIN("common_texture_space", tests)
