/* Vector identities of common/vec3.h and the ray of common/ray.h. */
#include "ray.h"
#include "suite.h"

/* One rounding per operation: a dot product of three terms is within
 * 3 REAL_EPSILON of the exact value, relative to the sum of |terms|. */
#define EPS ((double)REAL_EPSILON)

static const vec3 samples[] = {
    {1, 2, 3}, {-4, (real)0.5, 2}, {(real)0.1, (real)-0.7, (real)0.3}, {1000, -2000, (real)0.001}, {0, 0, 1},
};
enum { N_SAMPLES = sizeof samples / sizeof samples[0] };

static void test_right_handed_axes(void **state)
{
    (void)state;
    vec3 x = {1, 0, 0}, y = {0, 1, 0}, z = {0, 0, 1};
    assert_vec3_close(z, vec3_cross(x, y), 0); /* x cross y = z, exactly */
    assert_vec3_close(x, vec3_cross(y, z), 0);
    assert_vec3_close(y, vec3_cross(z, x), 0);
    assert_vec3_close(vec3_neg(z), vec3_cross(y, x), 0);
}

static void test_cross_is_perpendicular_and_anticommutative(void **state)
{
    (void)state;
    for (int i = 0; i < N_SAMPLES; i++) {
        for (int j = 0; j < N_SAMPLES; j++) {
            vec3 a = samples[i], b = samples[j];
            vec3 c = vec3_cross(a, b);
            /* a . (a x b) = 0 up to rounding: each product in c carries
             * 2 eps relative error of |a||b|, the dot adds 3 eps of |a||c|. */
            double la = vec3_length(a), lb = vec3_length(b);
            assert_close(0, vec3_dot(a, c), 8 * EPS * la * la * lb);
            assert_close(0, vec3_dot(b, c), 8 * EPS * la * lb * lb);
            vec3 d = vec3_cross(b, a);
            assert_vec3_close(vec3_neg(c), d, 0); /* the same products, swapped: exact */
        }
    }
}

static void test_lagrange_identity(void **state)
{
    (void)state;
    /* |a x b|^2 + (a . b)^2 = |a|^2 |b|^2 */
    for (int i = 0; i < N_SAMPLES; i++) {
        for (int j = 0; j < N_SAMPLES; j++) {
            vec3 a = samples[i], b = samples[j];
            double lhs = vec3_length_squared(vec3_cross(a, b)) + (double)vec3_dot(a, b) * vec3_dot(a, b);
            double rhs = (double)vec3_length_squared(a) * vec3_length_squared(b);
            assert_close(rhs, lhs, 16 * EPS * rhs);
        }
    }
}

static void test_dot_and_length(void **state)
{
    (void)state;
    assert_close(32, vec3_dot(vec3_make(1, 2, 3), vec3_make(4, 5, 6)), 0); /* small integers: exact */
    assert_close(5, vec3_length(vec3_make(3, 4, 0)), 0);                   /* sqrt is correctly rounded */
    assert_close(13, vec3_length(vec3_make(3, 4, 12)), 0);
    assert_close(6, vec3_max_abs(vec3_make(-6, 5, 1)), 0);
}

static void test_normalize_gives_unit_length(void **state)
{
    (void)state;
    for (int i = 0; i < N_SAMPLES; i++) {
        vec3 n = vec3_normalize(samples[i]);
        /* length, division and the three products: a few eps each */
        assert_close(1, vec3_length(n), 4 * EPS);
        /* same direction: n x a = 0 relative to |a| */
        vec3 c = vec3_cross(n, samples[i]);
        assert_close(0, vec3_length(c), 8 * EPS * vec3_length(samples[i]));
    }
}

static void test_add_sub_scale_mul(void **state)
{
    (void)state;
    vec3 a = {1, 2, 3}, b = {(real)0.5, -1, 4};
    assert_vec3_close(vec3_make((real)1.5, 1, 7), vec3_add(a, b), 0);
    assert_vec3_close(vec3_make((real)0.5, 3, -1), vec3_sub(a, b), 0);
    assert_vec3_close(vec3_make(-2, -4, -6), vec3_scale(a, -2), 0);
    assert_vec3_close(vec3_make((real)0.5, -2, 12), vec3_mul(a, b), 0);
    assert_true(vec3_is_finite(a));
    assert_false(vec3_is_finite(vec3_make(1, REAL_INFINITY, 0)));
    assert_false(vec3_is_finite(vec3_make(1, 0, (real)NAN)));
}

static void test_ray_at(void **state)
{
    (void)state;
    ray r = {{1, 2, 3}, {0, 0, -2}};
    assert_vec3_close(r.p, ray_at(r, 0), 0);
    assert_vec3_close(vec3_make(1, 2, 1), ray_at(r, 1), 0); /* p + t d */
    assert_vec3_close(vec3_make(1, 2, 4), ray_at(r, (real)-0.5), 0);
    /* d and 2d: the same point at half the t */
    ray r2 = {r.p, vec3_scale(r.d, 2)};
    assert_vec3_close(ray_at(r, 3), ray_at(r2, (real)1.5), 0);
}

/* Huge and tiny vectors: a . a overflows or underflows, |a| and a/|a| do
 * not.  (3, 4, 12) has length 13; scaled by a power of two the length
 * scales exactly, so the only errors are those of the ordinary case: one
 * sqrt and a few roundings, within 4 REAL_EPSILON relative. */
static void test_length_and_normalize_of_huge_and_tiny_vectors(void **state)
{
    (void)state;
    const real scales[] = {real_pow(2, 100), real_pow(2, -100), REAL_MAX / 16, REAL_MIN * 4, REAL_MIN / 1024};
    for (size_t k = 0; k < sizeof scales / sizeof scales[0]; k++) {
        real s = scales[k];
        vec3 a = vec3_make(3 * s, -4 * s, 12 * s);
        assert_close(1, vec3_length(a) / (13 * s), 4 * REAL_EPSILON);
        vec3 n = vec3_normalize(a);
        assert_vec3_close(vec3_make((real)3 / 13, (real)-4 / 13, (real)12 / 13), n, 4 * REAL_EPSILON);
    }
    assert_close(0, vec3_length(vec3_make(0, 0, 0)), 0);
}

/* The parity of whole numbers without converting them to an integer type. */
static void test_parity_is_range_safe(void **state)
{
    (void)state;
    assert_true(real_is_odd(7));
    assert_true(real_is_odd(-3));
    assert_false(real_is_odd(0));
    assert_false(real_is_odd(-8));
    assert_true(real_is_odd(real_pow(2, 20) + 1)); /* exact in float too */
    assert_false(real_is_odd((real)1e19));  /* beyond 2^63: even, with no undefined conversion */
    assert_false(real_is_odd(-REAL_MAX));
    assert_false(real_is_odd(REAL_INFINITY));
    assert_false(real_is_odd((real)NAN));
}

/* The ceiling and the floor in the build's type (a cell's first and last
 * index, chapter 11): every value here is exact in float, so the answers are
 * exact too, and the ceiling of a negative value above -1 is -0. */
static void test_ceil_and_floor(void **state)
{
    (void)state;
    assert_int_equal(sizeof(real), sizeof real_ceil((real)1.5));
    assert_int_equal(sizeof(real), sizeof real_floor((real)1.5));
    assert_close(3, real_ceil((real)2.25), 0);
    assert_close(-2, real_ceil((real)-2.25), 0);
    assert_close(3, real_ceil((real)3), 0);
    assert_close(8388608, real_ceil((real)8388607.5), 0); /* 2^23 - 1/2, the last half float */
    assert_true(real_ceil((real)-0.5) == 0 && signbit(real_ceil((real)-0.5)));
    assert_close(-3, real_floor((real)-2.25), 0);
    assert_close(2, real_floor((real)2.25), 0);
    for (int k = -40; k <= 40; k++) { /* ceil x = -floor(-x), in steps of 1/8 */
        const real x = (real)k / 8;
        assert_close(-real_floor(-x), real_ceil(x), 0);
    }
}

static const graded_test tests[] = {
    GRADED(test_right_handed_axes, 0),
    GRADED(test_cross_is_perpendicular_and_anticommutative, 0),
    GRADED(test_lagrange_identity, 0),
    GRADED(test_dot_and_length, 0),
    GRADED(test_normalize_gives_unit_length, 0),
    GRADED(test_add_sub_scale_mul, 0),
    GRADED(test_ray_at, 0),
    GRADED(test_length_and_normalize_of_huge_and_tiny_vectors, 0),
    GRADED(test_parity_is_range_safe, 0),
    GRADED(test_ceil_and_floor, 0),
};
SUITE_MAIN("common_vec", tests)
