/* Chapter 10: barycentric interpolation, texture lookups (wrap, clamp, nearest,
 * bilinear), the interpolated shading normal, textured shading. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "05_lambert/renderer/shading_stage.h"
#include "08_mirrors/mirror.h"
#include "10_interpolation/scenes/interp_scene.h"
#include "10_interpolation/shade_interp.h"
#include "10_interpolation/interpolate.h"
#include "10_interpolation/shading_normal.h"
#include "10_interpolation/scenes/sphere_mesh.h"
#include "sphere_uv.h"
#include "10_interpolation/texture.h"
#include "scene_build.h"
#include "suite.h"

/* A few roundings of values of size about 1 (see test_05_lambert.c). */
#define TOL(size) (32 * REAL_EPSILON * (size))

static const double pi = 3.14159265358979323846;

/* Random numbers (a fixed seed: the same numbers on every run). */
static unsigned long rng = 424242;
static double uniform(void) { return suite_uniform(&rng); }
static real between(double lo, double hi) { return (real)(lo + (hi - lo) * uniform()); }
static vec3 random_vec3(double size)
{
    /* one after another: the order of a call's arguments is the compiler's choice */
    real x = between(-size, size), y = between(-size, size), z = between(-size, size);
    return vec3_make(x, y, z);
}

/* Each component of got within tolerance of expected (as assert_vec3_why judges it). */
static int vec3_within(vec3 expected, vec3 got, double tolerance)
{
    return fabs((double)(got.x - expected.x)) <= tolerance && fabs((double)(got.y - expected.y)) <= tolerance &&
           fabs((double)(got.z - expected.z)) <= tolerance;
}

/* The suspects of in[0..n) whose value is got's (within tolerance), each
 * text once (several variants of one mistake may give the same texel), into
 * out; returns how many. */
static size_t matching_once(suspect_vec3 *out, const suspect_vec3 *in, size_t n, vec3 got, double tolerance)
{
    size_t kept = 0;
    for (size_t k = 0; k < n; k++) {
        int seen = !vec3_within(in[k].value, got, tolerance);
        for (size_t j = 0; j < kept && !seen; j++)
            seen = out[j].mistake == in[k].mistake;
        if (!seen)
            out[kept++] = in[k];
    }
    return kept;
}

/* ---- barycentric interpolation ---------------------------------------------------------------- */

/* The values typical mistakes of interpolate_vec3 give for A_a, A_b, A_c at
 * (beta, gamma), and what to say about each. */
#define INTERPOLATE_MISTAKES 16
/* v normalized, or v itself when it is the zero vector (which has no direction). */
static vec3 normalized_or_zero(vec3 v) { return vec3_length_squared(v) > 0 ? vec3_normalize(v) : v; }
static void interpolate_mistakes(suspect_vec3 mistakes[INTERPOLATE_MISTAKES], vec3 A_a, vec3 A_b, vec3 A_c, real beta,
                                 real gamma)
{
    real alpha = 1 - beta - gamma;
#define MIX(wa, wb, wc) vec3_add(vec3_add(vec3_scale(A_a, (wa)), vec3_scale(A_b, (wb))), vec3_scale(A_c, (wc)))
    const char *wrong_vertex = "the weights belong to the wrong vertices: alpha A_a + beta A_b + gamma A_c";
    const suspect_vec3 all[INTERPOLATE_MISTAKES] = {
        {MIX(alpha, gamma, beta), "beta and gamma swapped: beta weighs vertex b, gamma vertex c"},
        {MIX(beta, alpha, gamma), "alpha and beta swapped: alpha = 1 - beta - gamma weighs vertex a"},
        {MIX(gamma, beta, alpha), "alpha and gamma swapped: alpha = 1 - beta - gamma weighs vertex a"},
        {MIX(gamma, alpha, beta), wrong_vertex},
        {MIX(beta, gamma, alpha), wrong_vertex},
        {MIX(1 - beta, beta, gamma), "alpha = 1 - beta: the weight of vertex a is 1 - beta - gamma"},
        {MIX(1, beta, gamma), "vertex a's weight left out: A_a is scaled by alpha = 1 - beta - gamma"},
        {MIX(1 - gamma, beta, gamma), "alpha = 1 - gamma: the weight of vertex a is 1 - beta - gamma"},
        {MIX(beta + gamma, beta, gamma), "alpha = beta + gamma: it is 1 - beta - gamma"},
        {MIX(0, beta, gamma), "vertex a left out: A = alpha A_a + beta A_b + gamma A_c"},
        {MIX((real)(int)alpha, beta, gamma), "alpha converted to an int: (int)(1 - beta - gamma) is 0 inside the "
                                             "triangle; keep every weight a real"},
        {vec3_scale(MIX(alpha, beta, gamma), (real)(1.0 / 3)),
         "divided by 3: the weights already sum to 1 (alpha + beta + gamma = 1)"},
        {A_a, "A_a whatever beta and gamma: the exercise is still to do"},
        {normalized_or_zero(MIX(alpha, beta, gamma)),
         "the blend normalized: interpolate_vec3 blends any attribute (positions, (u, v)) and never normalizes; "
         "vertex_normal normalizes the blend of the normals"},
        {vec3_add(vec3_add(vec3_scale(normalized_or_zero(A_a), alpha), vec3_scale(normalized_or_zero(A_b), beta)),
                  vec3_scale(normalized_or_zero(A_c), gamma)),
         "each vertex's value normalized before the blend: the attributes are blended as they are (a normal is "
         "normalized after the blend, by vertex_normal)"},
        {vec3_add(vec3_add(A_a, vec3_scale(vec3_sub(A_b, A_a), beta)), vec3_scale(vec3_sub(A_c, A_a), gamma)),
         "A_a + beta (A_b - A_a) + gamma (A_c - A_a): the same blend in exact arithmetic, but its differences "
         "round, so that at a vertex it misses the vertex's own value; weigh each value as it is"},
    };
#undef MIX
    for (int k = 0; k < INTERPOLATE_MISTAKES; k++)
        mistakes[k] = all[k];
}

/* "A_a = (x, y, z), A_b = ..., A_c = ..., beta = b, gamma = c": an interpolation's input, for a message. */
static const char *interpolate_input(vec3 A_a, vec3 A_b, vec3 A_c, real beta, real gamma)
{
    return describe("A_a = (%.9g, %.9g, %.9g), A_b = (%.9g, %.9g, %.9g), A_c = (%.9g, %.9g, %.9g), beta = %.17g, "
                    "gamma = %.17g",
                    (double)A_a.x, (double)A_a.y, (double)A_a.z, (double)A_b.x, (double)A_b.y, (double)A_b.z,
                    (double)A_c.x, (double)A_c.y, (double)A_c.z, (double)beta, (double)gamma);
}

static const char *const interpolate_hint = "A = (1 - beta - gamma) A_a + beta A_b + gamma A_c";

/* interpolate_vec3(A_a, A_b, A_c, beta, gamma) is `expected` within
 * `tolerance`; a failure names the input and the mistake whose value was got. */
static void expect_interpolate(vec3 A_a, vec3 A_b, vec3 A_c, real beta, real gamma, vec3 expected, double tolerance)
{
    vec3 got = interpolate_vec3(A_a, A_b, A_c, beta, gamma);
    suspect_vec3 mistakes[INTERPOLATE_MISTAKES];
    interpolate_mistakes(mistakes, A_a, A_b, A_c, beta, gamma);
    assert_vec3_why(expected, got, tolerance,
                    describe("interpolate_vec3(%s)", interpolate_input(A_a, A_b, A_c, beta, gamma)), interpolate_hint,
                    mistakes, INTERPOLATE_MISTAKES);
}

/* At the vertices the attribute is the vertex's own, exactly (weights 1, 0,
 * 0); at an edge's midpoint the mean of its two ends; at the centroid the
 * mean of all three; at an inexact point inside, the blend. */
static void test_interpolate_vertices_edges(void **state)
{
    (void)state;
    vec3 A_a = {37.25, -12.5, 53.125}, A_b = {-3.75, 8.5, 0.625}, A_c = {1e3, -7e2, 2.5e2};
    expect_interpolate(A_a, A_b, A_c, 0, 0, A_a, 0);
    expect_interpolate(A_a, A_b, A_c, 1, 0, A_b, 0);
    expect_interpolate(A_a, A_b, A_c, 0, 1, A_c, 0);
    vec3 mid_ab = vec3_scale(vec3_add(A_a, A_b), (real)0.5), mid_bc = vec3_scale(vec3_add(A_b, A_c), (real)0.5);
    expect_interpolate(A_a, A_b, A_c, 0.5, 0, mid_ab, TOL(60));
    expect_interpolate(A_a, A_b, A_c, 0.5, 0.5, mid_bc, TOL(1000));
    vec3 centroid = vec3_scale(vec3_add(vec3_add(A_a, A_b), A_c), (real)(1.0 / 3));
    expect_interpolate(A_a, A_b, A_c, (real)(1.0 / 3), (real)(1.0 / 3), centroid, TOL(1000));
    /* beta = 0.2, gamma = 0.7, alpha = 0.1 (inexact in binary), in double:
     * three products and two sums of terms up to 700, a few roundings of 1000 */
    vec3 blend = vec3_make((real)(0.1 * 37.25 + 0.2 * -3.75 + 0.7 * 1e3), (real)(0.1 * -12.5 + 0.2 * 8.5 + 0.7 * -7e2),
                           (real)(0.1 * 53.125 + 0.2 * 0.625 + 0.7 * 2.5e2));
    expect_interpolate(A_a, A_b, A_c, (real)0.2, (real)0.7, blend, TOL(1000));
    /* The vertices' own values again where their differences round (0.7 - 0.1, 1 - 1e16): the weights 1, 0, 0
     * give each exactly */
    const vec3 B_a = {(real)0.7, (real)1e16, (real)-0.3}, B_b = {(real)0.1, 1, (real)0.9},
               B_c = {(real)-2.3, (real)0.3, (real)7.1};
    expect_interpolate(B_a, B_b, B_c, 0, 0, B_a, 0);
    expect_interpolate(B_a, B_b, B_c, 1, 0, B_b, 0);
    expect_interpolate(B_a, B_b, B_c, 0, 1, B_c, 0);
}

/* Interpolating the vertex POSITIONS gives back the point itself: chapter
 * 03's a + beta (b - a) + gamma (c - a), for random triangles far from the
 * origin and random (beta, gamma) inside; and every attribute is linear: the
 * interpolation of A + B is the sum of the interpolations (up to rounding). */
static void test_interpolate_random(void **state)
{
    (void)state;
    for (int k = 0; k < 1000; k++) {
        vec3 offset = random_vec3(100);
        vec3 a = vec3_add(offset, random_vec3(3)), b = vec3_add(offset, random_vec3(3)),
             c = vec3_add(offset, random_vec3(3));
        real beta = between(0, 1), gamma = between(0, 1 - beta);
        vec3 point = vec3_add(a, vec3_add(vec3_scale(vec3_sub(b, a), beta), vec3_scale(vec3_sub(c, a), gamma)));
        /* each term rounds relative to |offset| + 3 <= ~176 */
        expect_interpolate(a, b, c, beta, gamma, point, TOL(200));
        vec3 A[3] = {random_vec3(1), random_vec3(1), random_vec3(1)};
        vec3 B[3] = {random_vec3(1), random_vec3(1), random_vec3(1)};
        vec3 sum = vec3_add(interpolate_vec3(A[0], A[1], A[2], beta, gamma),
                            interpolate_vec3(B[0], B[1], B[2], beta, gamma));
        vec3 of_sum = interpolate_vec3(vec3_add(A[0], B[0]), vec3_add(A[1], B[1]), vec3_add(A[2], B[2]), beta, gamma);
        assert_vec3_why(sum, of_sum, TOL(8),
                        describe("interpolate_vec3 of A + B against interpolate_vec3 of A plus of B, at beta = %.17g, "
                                 "gamma = %.17g",
                                 (double)beta, (double)gamma),
                        "the interpolation is linear in the attributes: each vertex's value times its weight, "
                        "nothing added or multiplied that depends on the values",
                        NULL, 0);
    }
}

/* interpolate_uv(a, b, c, beta, gamma) is (u, v) within `tolerance`.
 * interpolate_uv is given: it interpolates (u, v, 0) with interpolate_vec3,
 * so a failure names interpolate_vec3's mistake (its values as (u, v, 0)). */
static void expect_uv(mesh_uv a, mesh_uv b, mesh_uv c, real beta, real gamma, double u, double v, double tolerance)
{
    mesh_uv got = interpolate_uv(a, b, c, beta, gamma);
    vec3 A_a = {a.u, a.v, 0}, A_b = {b.u, b.v, 0}, A_c = {c.u, c.v, 0};
    suspect_vec3 mistakes[INTERPOLATE_MISTAKES];
    interpolate_mistakes(mistakes, A_a, A_b, A_c, beta, gamma);
    assert_vec3_why(vec3_make((real)u, (real)v, 0), vec3_make(got.u, got.v, 0), tolerance,
                    describe("interpolate_uv (given: interpolate_vec3 of (u, v, 0)) with %s, as (u, v, 0)",
                             interpolate_input(A_a, A_b, A_c, beta, gamma)),
                    interpolate_hint, mistakes, INTERPOLATE_MISTAKES);
}

/* Texture coordinates interpolate the same way (u and v each): at vertex b
 * exactly b's, inside the blend (a few roundings of values up to 2.5). */
static void test_interpolate_uv(void **state)
{
    (void)state;
    mesh_uv a = {0.125, 0.75}, b = {2.5, -1.25}, c = {-0.375, 0.5};
    expect_uv(a, b, c, 1, 0, 2.5, -1.25, 0);
    for (int k = 0; k < 100; k++) {
        real beta = between(0, 1), gamma = between(0, 1 - beta), alpha = 1 - beta - gamma;
        expect_uv(a, b, c, beta, gamma, alpha * a.u + beta * b.u + gamma * c.u, alpha * a.v + beta * b.v + gamma * c.v,
                  TOL(4));
    }
}

/* ---- texel indices: repeat and clamp ------------------------------------------------------------- */

static const char *kind_name(texture_kind kind) { return kind == TEXTURE_REPEAT ? "RepeatTexture" : "ClampTexture"; }

/* The texel index i reads, computed another way than the exercise: the
 * floor of i / n, and min / max. */
static long long wrapped(texture_kind kind, long long i, int n)
{
    if (kind == TEXTURE_REPEAT)
        return i - n * (i >= 0 ? i / n : -((-i + n - 1) / n));
    return i < 0 ? 0 : i > n - 1 ? n - 1 : i;
}

/* texel_index(kind, i, n) is `expected`; a failure names the mistake. */
static void expect_index(texture_kind kind, long long i, int n, long long expected)
{
    int got = texel_index(kind, i, n);
    long long r = i % n;                                                           /* C's remainder */
    long long as_int = (long long)(int32_t)(uint32_t)(unsigned long long)i % n; /* i converted to int first */
    long long mask = i & (n - 1);                                                /* two's complement, any n */
    const suspect repeat_mistakes[] = {
        {(double)r, "C's % keeps the sign of i (-1 % n is -1): add n to a negative remainder"},
        {(double)(r < 0 ? -r : r), "the remainder's absolute value mirrors the texture: add n to a negative remainder"},
        {(double)(r + n), "i % n + n is n too many for i >= 0: take it mod n again, or add n only when negative"},
        {(double)(r < 0 ? r + n - 1 : r), "a negative remainder plus n - 1: -1 must become n - 1, so add n"},
        {(double)(r <= 0 ? r + n : r), "a remainder of 0 plus n: add n only to a negative remainder (m < 0, not m <= "
                                       "0); i = 0 reads texel 0"},
        {(double)(i < 0 ? 0 : r), "a negative i read as texel 0: a RepeatTexture wraps negative i too (-1 is the last "
                                  "texel, n - 1)"},
        {(double)mask, "i & (n - 1) is i mod n only when n is a power of two: take i % n (and add n when negative)"},
        {(double)(as_int < 0 ? as_int + n : as_int), "i converted to int before the %: i is a long long and may be "
                                                      "far beyond an int's range"},
        {(double)wrapped(TEXTURE_CLAMP, i, n), "clamped: a RepeatTexture wraps (i mod n)"},
    };
    const suspect clamp_mistakes[] = {
        {(double)n, "clamped to n (or only i > n clamped): the last texel is n - 1, and every i >= n reads it"},
        {(double)i, i < 0 ? "a negative i is not clamped: it reads texel 0"
                          : "i >= n is not clamped (i > n lets i = n through): it reads texel n - 1"},
        {(double)wrapped(TEXTURE_REPEAT, i, n), "wrapped: a ClampTexture clamps to [0, n - 1] (tex->kind decides)"},
        {(double)(n > 1 ? n - 2 : 0), "clamped to n - 2: the last texel is n - 1"},
    };
    if (kind == TEXTURE_REPEAT)
        assert_close_why(expected, got, 0, describe("texel_index(%s, i = %lld, n = %d)", kind_name(kind), i, n),
                         "RepeatTexture: i mod n in [0, n), also for negative i", repeat_mistakes,
                         sizeof repeat_mistakes / sizeof repeat_mistakes[0]);
    else
        assert_close_why(expected, got, 0, describe("texel_index(%s, i = %lld, n = %d)", kind_name(kind), i, n),
                         "ClampTexture: i clamped to [0, n - 1]", clamp_mistakes,
                         sizeof clamp_mistakes / sizeof clamp_mistakes[0]);
}

/* RepeatTexture: i mod n in [0, n), negative i included (-1 is the last
 * column), far beyond the image too, beyond an int's range (2^40 converted
 * to int is 0, but 2^40 mod 7 is 2); against i - n floor(i / n). */
static void test_texel_index_repeat(void **state)
{
    (void)state;
    expect_index(TEXTURE_REPEAT, 0, 7, 0);
    expect_index(TEXTURE_REPEAT, 6, 7, 6);
    expect_index(TEXTURE_REPEAT, 7, 7, 0);
    expect_index(TEXTURE_REPEAT, -1, 7, 6);
    expect_index(TEXTURE_REPEAT, -7, 7, 0);
    expect_index(TEXTURE_REPEAT, -9, 7, 5);
    expect_index(TEXTURE_REPEAT, 12345, 1, 0);
    for (long long i = -1000; i <= 1000; i += 37)
        for (int n = 1; n < 300; n += 41) {
            long long expected = i - n * (long long)floor((double)i / n);
            expect_index(TEXTURE_REPEAT, i, n, expected);
        }
    expect_index(TEXTURE_REPEAT, 1099511627776LL, 256, 1099511627776LL % 256);
    expect_index(TEXTURE_REPEAT, -1099511627777LL, 256, 256 - 1099511627777LL % 256);
    expect_index(TEXTURE_REPEAT, 1099511627776LL, 7, 2);             /* 2^40 = 8^13 2 = 2 mod 7 */
    expect_index(TEXTURE_REPEAT, 3 * 1099511627776LL + 5, 300, 233);  /* 2^40 = 76 mod 300: 3 76 + 5 */
    expect_index(TEXTURE_REPEAT, -3 * 1099511627776LL - 5, 300, 67); /* 300 - 233 */
}

/* ClampTexture: indices before the image read its first texel, beyond it its last. */
static void test_texel_index_clamp(void **state)
{
    (void)state;
    expect_index(TEXTURE_CLAMP, -1, 7, 0);
    expect_index(TEXTURE_CLAMP, -1099511627776LL, 7, 0);
    expect_index(TEXTURE_CLAMP, 3, 7, 3);
    expect_index(TEXTURE_CLAMP, 6, 7, 6);
    expect_index(TEXTURE_CLAMP, 7, 7, 6);
    expect_index(TEXTURE_CLAMP, 8, 7, 6);
    expect_index(TEXTURE_CLAMP, 1099511627776LL, 7, 6);
    expect_index(TEXTURE_CLAMP, 5, 1, 0);
    expect_index(TEXTURE_CLAMP, -1, 1, 0);
}

/* ---- texture lookups -------------------------------------------------------------------------- */

/* A W x H texture whose texel (x, y) is (x, y, 7) / 255: a texel names its place. */
#define TW 5
#define TH 3
static unsigned char texels[TW * TH * 3];
static scene_texture numbered(texture_kind kind)
{
    for (int y = 0; y < TH; y++)
        for (int x = 0; x < TW; x++) {
            unsigned char *p = texels + (y * TW + x) * 3;
            p[0] = (unsigned char)(10 * x);
            p[1] = (unsigned char)(10 * y);
            p[2] = 7;
        }
    return (scene_texture){.kind = kind, .image = {.width = TW, .height = TH, .rgb = texels}};
}

/* The colour of texel (x, y) of `numbered`. */
static vec3 numbered_colour(long long x, long long y)
{
    return vec3_make((real)(10 * x) / 255, (real)(10 * y) / 255, (real)7 / 255);
}

/* The continuous texel coordinate s n as texture.c computes it (in real),
 * held within +-2^40, NaN as 0: the rounding is then the same. */
static double coordinate(real s, int n)
{
    real x = s * (real)n;
    double limit = 1099511627776.0;
    return x != x ? 0 : fmax(-limit, fmin(limit, (double)x));
}

/* A lookup reads the texels texel_index gives, so a lookup that is wrong
 * where texel_index is wrong is the wrap's mistake, not the lookup's: when
 * the student's texel_index(kind, i, n) is not the wrapped index, says so
 * (the index of the `axis` a right lookup asks for, what texel_index gave,
 * and the test that names the wrap's mistake); else NULL. */
static const char *wrap_mistake(texture_kind kind, long long i, int n, const char *axis)
{
    int got = texel_index(kind, i, n);
    long long expected = wrapped(kind, i, n);
    if (got == expected)
        return NULL;
    return describe("the wrap, not the lookup: the %s index %lld of a texture %d texels %s is texel %lld, but "
                    "texel_index(%s, %lld, %d) gives %d (test_texel_index_%s names the wrap's mistake)",
                    axis, i, n, axis[0] == 'c' ? "wide" : "high", expected, kind_name(kind), i, n, got,
                    kind == TEXTURE_REPEAT ? "repeat" : "clamp");
}

static long long llmin(long long a, long long b) { return a < b ? a : b; }

/* texture_nearest(tex, uv) on a `numbered` texture reads texel (x, y); a
 * failure names the texel read (its colour says which) and the mistake. */
static void expect_nearest(const scene_texture *tex, mesh_uv uv, int x, int y)
{
    color c = texture_nearest(tex, uv);
    texture_kind k = tex->kind, other = k == TEXTURE_REPEAT ? TEXTURE_CLAMP : TEXTURE_REPEAT;
    double X = coordinate(uv.u, TW), Y = coordinate(1 - uv.v, TH);
    long long cx = (long long)(X + 0.5), cy = (long long)(Y + 0.5); /* the course's rounding */
    long long col = wrapped(k, cx, TW), row = wrapped(k, cy, TH);
    const char *half = "dropped the fraction without adding 1/2 first (1 / 2 in integers is 0: write 0.5): the "
                       "nearest texel is (long long)(x + 1/2)";
    const suspect_vec3 mistakes[] = {
        {numbered_colour(row, col), "u and v swapped: the column comes from x = u W, the row from y = (1 - v) H "
                                    "(texture_image_texel(img, column, row))"},
        {numbered_colour(wrapped(k, (long long)X, TW), wrapped(k, (long long)Y, TH)), half},
        {numbered_colour(wrapped(k, (long long)X, TW), row), half},
        {numbered_colour(col, wrapped(k, (long long)Y, TH)), half},
        {numbered_colour(col, TH - 1 - row), "v flipped twice: y = (1 - v) H counts rows from the top already"},
        {numbered_colour(col, wrapped(k, (long long)(coordinate(uv.v, TH) + 0.5), TH)),
         "v not flipped: rows count down from the top, y = (1 - v) H"},
        {numbered_colour(wrapped(k, (long long)ceil(X), TW), wrapped(k, (long long)ceil(Y), TH)),
         "ceil(x) rounds every fraction up: the nearest texel is (long long)(x + 1/2)"},
        {numbered_colour(wrapped(k, (long long)floor(X + 0.5), TW), wrapped(k, (long long)floor(Y + 0.5), TH)),
         "floor(x + 1/2) or round(x): the course's solution drops the fraction, (long long)(x + 1/2), which rounds towards zero "
         "and differs for x < -1/2"},
        {numbered_colour(wrapped(k, (long long)(X - 0.5), TW), wrapped(k, (long long)(Y - 0.5), TH)),
         "x - 1/2: the nearest texel is (long long)(x + 1/2)"},
        /* an index wrapped by the other side may lie outside the image: texture_image_texel reads the edge */
        {numbered_colour(col, llmin(wrapped(k, cy, TW), TH - 1)), "the row wrapped by the width: rows wrap by the height"},
        {numbered_colour(llmin(wrapped(k, cx, TH), TW - 1), row), "the column wrapped by the height: columns wrap by the "
                                                                  "width"},
        {numbered_colour(wrapped(other, cx, TW), wrapped(other, cy, TH)),
         "wrapped the other way: tex->kind says repeat or clamp (texel_index)"},
        /* texture_image_texel keeps an index outside the image at the edge: clamped */
        {numbered_colour(wrapped(TEXTURE_CLAMP, cx, TW), wrapped(TEXTURE_CLAMP, cy, TH)),
         "not wrapped: each index goes through texel_index(tex->kind, i, n) (texture_image_texel only keeps it inside "
         "the image)"},
        {numbered_colour(0, 0), fabs(X) > 2147483647.0 || fabs(Y) > 2147483647.0
                                    ? "texel (0, 0) for a coordinate beyond an int's range: the index converted to "
                                      "int overflowed; keep it a long long"
                                    : "texel (0, 0) whatever (u, v): the exercise is still to do"},
    };
    vec3 expected = numbered_colour(x, y), got = vec3_make(c.r, c.g, c.b);
    const char *input = describe("texture_nearest(%s %dx%d, u = %.9g, v = %.9g): x = u W = %.9g, y = (1 - v) H = "
                                 "%.9g; texel (i, j) is (10 i, 10 j, 7) / 255: expected texel (%d, %d)",
                                 kind_name(k), TW, TH, (double)uv.u, (double)uv.v, X, Y, x, y);
    /* a wrong texel where texel_index is wrong: the wrap is named, not a rounding */
    const char *wrap = NULL;
    if (!vec3_within(expected, got, TOL(1)) && !(wrap = wrap_mistake(k, cx, TW, "column")))
        wrap = wrap_mistake(k, cy, TH, "row");
    suspect_vec3 named[sizeof mistakes / sizeof mistakes[0]];
    size_t n = matching_once(named, mistakes, sizeof mistakes / sizeof mistakes[0], got, TOL(1));
    if (wrap)
        assert_vec3_why(expected, got, TOL(1), input, wrap, NULL, 0);
    else
        assert_vec3_why(expected, got, TOL(1), input,
                        "column (long long)(x + 1/2), row (long long)(y + 1/2), each wrapped by texel_index", named, n);
}

/* Nearest: texel (x, y) is centred on u = x / W, v = 1 - y / H (v up, rows
 * down); it is read from half a texel before its centre to half a texel
 * after.  Beyond the image: repeated or clamped. */
static void test_nearest(void **state)
{
    (void)state;
    for (int kind = 0; kind < 2; kind++) {
        scene_texture tex = numbered((texture_kind)kind);
        for (int y = 0; y < TH; y++)
            for (int x = 0; x < TW; x++) {
                for (double du = -0.49; du < 0.5; du += 0.245) { /* anywhere within half a texel of the centre */
                    if (x + du < 0 || y - du < 0)
                        continue; /* (before the first centre: see test_nearest_quirk) */
                    mesh_uv uv = {(real)((x + du) / TW), (real)(1 - (y - du) / TH)};
                    expect_nearest(&tex, uv, x, y);
                }
            }
        /* v = 1 is the top row, v just above 0 the bottom row */
        expect_nearest(&tex, (mesh_uv){0, 1}, 0, 0);
        expect_nearest(&tex, (mesh_uv){(real)(2.0 / TW), (real)0.2}, 2, TH - 1);
        /* beyond the right edge: column 0 again, or the last column */
        expect_nearest(&tex, (mesh_uv){(real)(1 + 1.1 / TW), (real)(1 - 1.0 / TH)}, kind == TEXTURE_REPEAT ? 1 : TW - 1, 1);
        /* y = 3.8, row index 4 of a texture 3 high: row 1 repeated, the last row clamped (wrapped by the width
         * 5 it would be 4, outside the image) */
        expect_nearest(&tex, (mesh_uv){(real)(2.0 / TW), (real)(1 - 3.8 / TH)}, 2, kind == TEXTURE_REPEAT ? 1 : TH - 1);
        /* u + 3, v - 2 read what u, v read when repeated */
        if (kind == TEXTURE_REPEAT)
            expect_nearest(&tex, (mesh_uv){(real)(3 + 3.2 / TW), (real)(-2 + 1 - 2.1 / TH)}, 3, 2);
        else
            expect_nearest(&tex, (mesh_uv){(real)(3 + 3.2 / TW), (real)(-2 + 1 - 2.1 / TH)}, TW - 1, TH - 1);
    }
}

/* The course's rounding: add 1/2, drop the fraction (towards zero).  For
 * u W >= -1/2 that is the nearest texel; below, every index comes out one
 * more than the nearest: texel 0 is read from u W = -3/2 (not -1/2) to 1/2,
 * and (-5/2, -3/2) reads column -1 (the last of a repeating texture), where
 * the nearest would be -2.  The course's images show it (the tiled floor of
 * teapot.xml), so it is kept. */
static void test_nearest_quirk(void **state)
{
    (void)state;
    scene_texture tex = numbered(TEXTURE_REPEAT);
    real v = (real)(1 - 1.0 / TH); /* row 1 */
    expect_nearest(&tex, (mesh_uv){(real)(-0.3 / TW), v}, 0, 1);
    expect_nearest(&tex, (mesh_uv){(real)(-0.8 / TW), v}, 0, 1);
    expect_nearest(&tex, (mesh_uv){(real)(-1.4 / TW), v}, 0, 1);
    expect_nearest(&tex, (mesh_uv){(real)(-1.7 / TW), v}, TW - 1, 1);
    expect_nearest(&tex, (mesh_uv){(real)(-2.4 / TW), v}, TW - 1, 1);
    expect_nearest(&tex, (mesh_uv){(real)(-2.6 / TW), v}, TW - 2, 1);
    /* rows the same way: v above 1 + 1/(2H) */
    expect_nearest(&tex, (mesh_uv){(real)(2.0 / TW), (real)(1 + 1.2 / TH)}, 2, 0);
    expect_nearest(&tex, (mesh_uv){(real)(2.0 / TW), (real)(1 + 1.7 / TH)}, 2, TH - 1);
    /* NaN and huge coordinates read something, without undefined behaviour */
    expect_nearest(&tex, (mesh_uv){(real)NAN, (real)1}, 0, 0);
    scene_texture clamp = numbered(TEXTURE_CLAMP);
    expect_nearest(&clamp, (mesh_uv){(real)1e30, (real)1e30}, TW - 1, 0);
    expect_nearest(&clamp, (mesh_uv){(real)-1e30, (real)-1e30}, 0, TH - 1);
}

/* What a bilinear lookup gives, and what some mistakes give instead. */
typedef enum {
    BILINEAR_RIGHT,
    BILINEAR_MINUS_HALF, /* centres at x + 1/2: x0 = floor(x - 1/2) */
    BILINEAR_PLUS_HALF,  /* nearest's + 1/2: x0 = floor(x + 1/2) */
    BILINEAR_S_SWAPPED,  /* T(x0) weighs s, T(x0 + 1) weighs 1 - s */
    BILINEAR_S_SWAPPED_TOP,
    BILINEAR_S_SWAPPED_BOTTOM,
    BILINEAR_T_SWAPPED,
    BILINEAR_T_IS_S,     /* t = x - x0 */
    BILINEAR_BOTTOM_T,   /* the bottom row blended with t instead of s */
    BILINEAR_TRUNCATE,   /* x0 = (long long)x: towards zero */
    BILINEAR_ROW_ABOVE,  /* the second row is y0 - 1 */
    BILINEAR_NO_WRAP,    /* x0 + 1 and y0 + 1 not wrapped: the edge texel again */
    BILINEAR_NO_WRAP_X,
    BILINEAR_NO_WRAP_Y,
    BILINEAR_UV_SWAPPED, /* texel (row, column) */
    BILINEAR_NEAREST,    /* the nearest texel */
    BILINEAR_MINUS_HALF_INDEX, /* x0 = floor(x - 1/2), but s = x - x0: the fraction not taken after the shift */
    BILINEAR_PLUS_HALF_INDEX,  /* x0 = floor(x + 1/2), s = x - x0 */
    BILINEAR_CORNER,     /* T(x0, y0) weighs s t: the weights of the opposite corner */
    BILINEAR_PLUS_ONE,   /* x1 = x0 + 1 and y1 = y0 + 1 from the wrapped x0, y0: read at the edge */
    BILINEAR_PLUS_ONE_X,
    BILINEAR_PLUS_ONE_Y,
    BILINEAR_ROWS_BY_WIDTH, /* y0 and y1 wrapped by the width */
    BILINEAR_FRACTION_WRAPPED, /* s = x - x0 with x0 wrapped into the image */
    BILINEAR_ST_SWAPPED,       /* s = y - y0, t = x - x0 */
    BILINEAR_OTHER_KIND,       /* every index wrapped by the other kind of texture */
    BILINEAR_FRACTION_TRUNCATED, /* x0 = floor(x), but s = x - (long long)x: negative for x < 0 */
    BILINEAR_T_BOTH,           /* both rows weigh 1 - t */
    BILINEAR_VARIANTS
} bilinear_variant;

/* The texel at (x, y) wrapped as a texture of `kind` wraps. */
static vec3 texel_of_kind(const scene_texture *tex, texture_kind kind, long long x, long long y)
{
    color c = texture_image_texel(&tex->image, (int)wrapped(kind, x, tex->image.width),
                                  (int)wrapped(kind, y, tex->image.height));
    return vec3_make(c.r, c.g, c.b);
}

static vec3 texel_vec3(const scene_texture *tex, long long x, long long y) { return texel_of_kind(tex, tex->kind, x, y); }

/* The texel at (x, y) wrapped by the other kind of texture than tex's. */
static vec3 texel_other_kind(const scene_texture *tex, long long x, long long y)
{
    return texel_of_kind(tex, tex->kind == TEXTURE_REPEAT ? TEXTURE_CLAMP : TEXTURE_REPEAT, x, y);
}

/* The texel at (x, y) read with the column and the row swapped, each wrapped by its own side and then
 * kept inside the image as texture_image_texel keeps an index outside it: at the edge. */
static vec3 texel_swapped(const scene_texture *tex, long long x, long long y)
{
    int W = tex->image.width, H = tex->image.height;
    color c = texture_image_texel(&tex->image, (int)llmin(wrapped(tex->kind, y, H), W - 1),
                                  (int)llmin(wrapped(tex->kind, x, W), H - 1));
    return vec3_make(c.r, c.g, c.b);
}

static vec3 bilinear_as(const scene_texture *tex, double x, double y, bilinear_variant v)
{
    int W = tex->image.width, H = tex->image.height;
    if (v == BILINEAR_NEAREST)
        return texel_vec3(tex, (long long)(x + 0.5), (long long)(y + 0.5));
    double shift = v == BILINEAR_MINUS_HALF ? -0.5 : v == BILINEAR_PLUS_HALF ? 0.5 : 0;
    double index_shift = v == BILINEAR_MINUS_HALF_INDEX ? -0.5 : v == BILINEAR_PLUS_HALF_INDEX ? 0.5 : 0;
    x += shift, y += shift;
    double fx = v == BILINEAR_TRUNCATE ? trunc(x) : floor(x + index_shift),
           fy = v == BILINEAR_TRUNCATE ? trunc(y) : floor(y + index_shift);
    double s = x - fx, t = v == BILINEAR_T_IS_S ? s : y - fy;
    if (v == BILINEAR_FRACTION_WRAPPED)
        s = x - (double)wrapped(tex->kind, (long long)fx, W), t = y - (double)wrapped(tex->kind, (long long)fy, H);
    if (v == BILINEAR_FRACTION_TRUNCATED)
        s = x - trunc(x), t = y - trunc(y);
    if (v == BILINEAR_ST_SWAPPED) {
        double s_was = s;
        s = t, t = s_was;
    }
    long long x0 = (long long)fx, y0 = (long long)fy, x1 = x0 + 1, y1 = v == BILINEAR_ROW_ABOVE ? y0 - 1 : y0 + 1;
    if (v == BILINEAR_NO_WRAP || v == BILINEAR_NO_WRAP_X)
        x1 = x1 >= 0 && x1 < W ? x1 : wrapped(tex->kind, x0, W);
    if (v == BILINEAR_NO_WRAP || v == BILINEAR_NO_WRAP_Y)
        y1 = y1 >= 0 && y1 < H ? y1 : wrapped(tex->kind, y0, H);
    /* one past the wrapped index, read as texture_image_texel reads an index outside: the edge */
    if (v == BILINEAR_PLUS_ONE || v == BILINEAR_PLUS_ONE_X)
        x1 = wrapped(tex->kind, x0, W) + 1 < W ? wrapped(tex->kind, x0, W) + 1 : W - 1;
    if (v == BILINEAR_PLUS_ONE || v == BILINEAR_PLUS_ONE_Y)
        y1 = wrapped(tex->kind, y0, H) + 1 < H ? wrapped(tex->kind, y0, H) + 1 : H - 1;
    if (v == BILINEAR_ROWS_BY_WIDTH) {
        y0 = llmin(wrapped(tex->kind, y0, W), H - 1);
        y1 = llmin(wrapped(tex->kind, y1, W), H - 1);
    }
    const int corner = v == BILINEAR_CORNER;
    double ws = corner || v == BILINEAR_S_SWAPPED || v == BILINEAR_S_SWAPPED_TOP ? 1 - s : s;
    double wb = v == BILINEAR_BOTTOM_T ? t : corner || v == BILINEAR_S_SWAPPED || v == BILINEAR_S_SWAPPED_BOTTOM ? 1 - s : s;
    double wt = corner || v == BILINEAR_T_SWAPPED ? 1 - t : t;
    vec3 (*T)(const scene_texture *, long long, long long) = v == BILINEAR_UV_SWAPPED   ? texel_swapped
                                                             : v == BILINEAR_OTHER_KIND ? texel_other_kind
                                                                                        : texel_vec3;
    vec3 top = vec3_add(vec3_scale(T(tex, x0, y0), (real)(1 - ws)), vec3_scale(T(tex, x1, y0), (real)ws));
    vec3 bottom = vec3_add(vec3_scale(T(tex, x0, y1), (real)(1 - wb)), vec3_scale(T(tex, x1, y1), (real)wb));
    return vec3_add(vec3_scale(top, (real)(1 - wt)), vec3_scale(bottom, (real)(v == BILINEAR_T_BOTH ? 1 - wt : wt)));
}

/* texture_bilinear(tex, uv) is `expected` within `tolerance` (`known` says
 * how the test knows it); a failure names the input and the mistake whose
 * value was got, or the wrap when texel_index is wrong for a texel the
 * blend needs. */
static void expect_bilinear_is(const scene_texture *tex, mesh_uv uv, vec3 expected, double tolerance,
                               const char *known)
{
    static const char *const why[BILINEAR_VARIANTS] = {
        [BILINEAR_MINUS_HALF] = "x - 1/2 (texel centres at x + 1/2): in this course texel i's centre is at x = i, "
                                "so x0 = floor(x) with x = u W",
        [BILINEAR_PLUS_HALF] = "nearest's + 1/2 carried over: the left column is x0 = floor(x), not floor(x + 1/2)",
        [BILINEAR_S_SWAPPED] = "the weights along x swapped: T(x0) weighs 1 - s and T(x0 + 1) weighs s",
        [BILINEAR_S_SWAPPED_TOP] = "the weights along x swapped in the top row: T(x0, y0) weighs 1 - s and T(x0 + 1, "
                                   "y0) weighs s",
        [BILINEAR_S_SWAPPED_BOTTOM] = "the weights along x swapped in the bottom row: T(x0, y0 + 1) weighs 1 - s "
                                      "and T(x0 + 1, y0 + 1) weighs s",
        [BILINEAR_T_SWAPPED] = "the weights along y swapped: the top row (y0) weighs 1 - t, the bottom one t",
        [BILINEAR_T_IS_S] = "t = x - x0: t is the fraction along y, y - y0",
        [BILINEAR_BOTTOM_T] = "the bottom row blended with t: both rows blend along x with s",
        [BILINEAR_TRUNCATE] = "(long long)x rounds towards zero: x0 = floor(x), also for x < 0 (s = x - x0 is in [0, 1))",
        [BILINEAR_ROW_ABOVE] = "the second row is y0 - 1: the rows are y0 = floor(y) and y0 + 1",
        [BILINEAR_NO_WRAP] = "x0 + 1 or y0 + 1 not wrapped by texel_index: across the edge a RepeatTexture blends in "
                             "the first column (row)",
        [BILINEAR_NO_WRAP_X] = "x0 + 1 not wrapped by texel_index: across the right edge a RepeatTexture blends "
                               "in the first column",
        [BILINEAR_NO_WRAP_Y] = "y0 + 1 not wrapped by texel_index: across the bottom edge a RepeatTexture blends "
                               "in the first row",
        [BILINEAR_UV_SWAPPED] = "u and v swapped: columns come from x = u W, rows from y = (1 - v) H "
                                "(texture_image_texel(img, column, row))",
        [BILINEAR_NEAREST] = "the nearest texel: blend the four texels around (x, y)",
        [BILINEAR_MINUS_HALF_INDEX] = "x0 = floor(x - 1/2) with s = x - x0: a half-texel shift of the index alone, "
                                      "the fraction not taken after it; in this course texel i's centre is at x = i: "
                                      "x0 = floor(x), s = x - x0",
        [BILINEAR_PLUS_HALF_INDEX] = "x0 = floor(x + 1/2) with s = x - x0: nearest's + 1/2 in the index alone; the "
                                     "left column is x0 = floor(x), s = x - x0 in [0, 1)",
        [BILINEAR_CORNER] = "the weights from the opposite corner: T(x0, y0) weighs (1 - s)(1 - t), T(x0 + 1, y0 + 1) "
                            "weighs s t",
        [BILINEAR_PLUS_ONE] = "x1 = x0 + 1 (y1 = y0 + 1) from the wrapped x0: past the last texel it is outside the "
                              "image; wrap x0 + 1 itself with texel_index (a RepeatTexture blends in the first column)",
        [BILINEAR_PLUS_ONE_X] = "x1 = x0 + 1 from the wrapped x0: past the last column it is outside the image; wrap "
                                "x0 + 1 itself with texel_index (a RepeatTexture blends in the first column)",
        [BILINEAR_PLUS_ONE_Y] = "y1 = y0 + 1 from the wrapped y0: past the last row it is outside the image; wrap "
                                "y0 + 1 itself with texel_index (a RepeatTexture blends in the first row)",
        [BILINEAR_ROWS_BY_WIDTH] = "the rows wrapped by the width: y0 and y0 + 1 wrap by the height",
        [BILINEAR_FRACTION_WRAPPED] = "the fractions from the wrapped indices: s = x - floor(x) and t = y - floor(y), "
                                      "before any wrapping (the wrap only picks the texels)",
        [BILINEAR_ST_SWAPPED] = "s and t swapped: s = x - x0 blends along x (the columns), t = y - y0 along y (the "
                                "rows)",
        [BILINEAR_OTHER_KIND] = "wrapped the other way: tex->kind says repeat or clamp (texel_index(tex->kind, i, n) "
                                "for each of the four indices)",
        [BILINEAR_FRACTION_TRUNCATED] = "the fraction of (long long)x: for x < 0 it is negative; s = x - floor(x) and t "
                                        "= y - floor(y), from the same floor as the indices",
        [BILINEAR_T_BOTH] = "both rows weighed 1 - t: the row y0 weighs 1 - t, the row y0 + 1 weighs t (the weights sum "
                            "to 1)",
    };
    double x = coordinate(uv.u, tex->image.width), y = coordinate(1 - uv.v, tex->image.height);
    suspect_vec3 mistakes[BILINEAR_VARIANTS + 1];
    size_t n = 0;
    for (int v = 1; v < BILINEAR_VARIANTS; v++)
        mistakes[n++] = (suspect_vec3){bilinear_as(tex, x, y, (bilinear_variant)v), why[v]};
    mistakes[n++] = (suspect_vec3){texel_vec3(tex, 0, 0), "texel (0, 0) whatever (u, v): the exercise is still to do"};
    color c = texture_bilinear(tex, uv);
    vec3 got = vec3_make(c.r, c.g, c.b);
    const char *input =
        describe("texture_bilinear(%s %dx%d, u = %.9g, v = %.9g): x = u W = %.9g, y = (1 - v) H = %.9g%s%s",
                 kind_name(tex->kind), tex->image.width, tex->image.height, (double)uv.u, (double)uv.v, x, y,
                 known ? "; " : "", known ? known : "");
    /* a wrong blend where texel_index is wrong for one of the four texels: the wrap is named */
    const char *wrap = NULL;
    long long x0 = (long long)floor(x), y0 = (long long)floor(y);
    for (int k = 0; k < 4 && !wrap && !vec3_within(expected, got, tolerance); k++)
        wrap = k < 2 ? wrap_mistake(tex->kind, x0 + k, tex->image.width, "column")
                     : wrap_mistake(tex->kind, y0 + k - 2, tex->image.height, "row");
    if (wrap)
        assert_vec3_why(expected, got, tolerance, input, wrap, NULL, 0);
    else
        assert_vec3_why(expected, got, tolerance, input,
                        "x0 = floor(x), y0 = floor(y), s = x - x0, t = y - y0; blend T(x0, y0), T(x0 + 1, y0) by s, "
                        "the same for row y0 + 1, then the two rows by t",
                        mistakes, n);
}

/* texture_bilinear(tex, uv) against the blend computed here.  x = u W and
 * y = (1 - v) H are computed as texture.c does; the fractions s, t then
 * agree to a rounding of x and y (eps |x| / 2 and eps |y| / 2: the weights
 * move by that much, the texels being in [0, 1]), and the result to that
 * plus a few roundings of size 1: 32 eps 4 + 2 eps (|x| + |y|), twice the
 * bound. */
static void expect_bilinear(const scene_texture *tex, mesh_uv uv)
{
    double x = coordinate(uv.u, tex->image.width), y = coordinate(1 - uv.v, tex->image.height);
    expect_bilinear_is(tex, uv, bilinear_as(tex, x, y, BILINEAR_RIGHT), TOL(4) + 2 * REAL_EPSILON * (fabs(x) + fabs(y)),
                       NULL);
}

/* Bilinear: at a texel's centre the texel itself; between centres the
 * linear blend (the texel values are linear in x and y, so the blend is the
 * same linear function); across the right edge a repeating texture blends
 * the last column with the first, a clamped one stays at the last. */
static void test_bilinear(void **state)
{
    (void)state;
    scene_texture tex = numbered(TEXTURE_CLAMP);
    for (int k = 0; k < 200; k++) {
        double x = uniform() * (TW - 1), y = uniform() * (TH - 1); /* between the first and last centres */
        vec3 linear = vec3_make((real)(10 * x / 255), (real)(10 * y / 255), (real)(7 / 255.0));
        expect_bilinear_is(&tex, (mesh_uv){(real)(x / TW), (real)(1 - y / TH)}, linear, TOL(16),
                           "texel (i, j) is (10 i, 10 j, 7) / 255, linear in i and j, so the blend at (x, y) is "
                           "(10 x, 10 y, 7) / 255");
    }
    expect_bilinear(&tex, (mesh_uv){(real)(3.0 / TW), (real)(1 - 1.0 / TH)});
    /* half-way between the last column and the one after it */
    real u = (real)((TW - 0.5) / TW), v = (real)(1 - 1.0 / TH);
    expect_bilinear_is(&tex, (mesh_uv){u, v}, numbered_colour(TW - 1, 1), TOL(4),
                       "clamped, the column after the last is the last: texel (4, 1) alone");
    scene_texture repeat = numbered(TEXTURE_REPEAT);
    vec3 last_first = vec3_scale(vec3_add(numbered_colour(TW - 1, 1), numbered_colour(0, 1)), (real)0.5);
    expect_bilinear_is(&repeat, (mesh_uv){u, v}, last_first, TOL(4),
                       "repeated, the column after the last is the first: (texel (4, 1) + texel (0, 1)) / 2");
    /* at every centre the texel itself (s = t = 0, up to the rounding of x = u W) */
    for (int y = 0; y < TH; y++)
        for (int x = 0; x < TW; x++) {
            mesh_uv at = {(real)((double)x / TW), (real)(1 - (double)y / TH)};
            expect_bilinear_is(&repeat, at, numbered_colour(x, y), TOL(4),
                               describe("at the centre of texel (%d, %d), that texel alone", x, y));
        }
    /* Huge coordinates, as test_nearest_quirk reads them: x = u W is held within +-2^40 (texel_coordinate),
     * beyond an int's range but not a long long's, so floor(x) goes to texel_index as a long long, never
     * through an int (an int conversion of 2^40 is undefined; x86 gives INT_MIN, which wraps elsewhere).
     * Each x and y here is a whole number, so s = t = 0 and the blend is one texel alone, exactly. */
    const char *const huge = "x = u W and y = (1 - v) H are whole numbers beyond an int's range (within 2^40): s = t "
                             "= 0, the one texel texel_index gives for floor(x), floor(y) as long longs (an int "
                             "conversion of floor(x) is undefined there)";
    /* 5 x 2^33 = 0 mod 5 */
    expect_bilinear_is(&repeat, (mesh_uv){(real)0x1p33, 1}, numbered_colour(0, 0), TOL(4),
                       describe("repeated, u = 2^33 (x = 5 x 2^33 = 0 mod 5), v = 1: texel (0, 0); %s", huge));
    expect_bilinear_is(&tex, (mesh_uv){(real)1e30, (real)-1e30}, numbered_colour(TW - 1, TH - 1), TOL(4),
                       describe("clamped, u = 1e30, v = -1e30: the last column, the last row; %s", huge));
}

/* Bilinear on a texture of random texels (so that each mistake gives its
 * own value), 7 x 4, repeated and clamped, at random (u, v) around and
 * beyond the image (negative x and y, both edges, u W and (1 - v) H up to
 * +-3 images away) and far away (u near 1000 and v near -1000, where the
 * fractions s and t come from large coordinates). */
static void test_bilinear_random(void **state)
{
    (void)state;
    static unsigned char random_texels[7 * 4 * 3];
    for (size_t k = 0; k < sizeof random_texels; k++)
        random_texels[k] = (unsigned char)(uniform() * 256);
    for (int kind = 0; kind < 2; kind++) {
        scene_texture tex = {.kind = (texture_kind)kind, .image = {.width = 7, .height = 4, .rgb = random_texels}};
        for (int k = 0; k < 400; k++) {
            real u = between(-3, 4), v = between(-3, 4);
            mesh_uv uv = {u, v};
            expect_bilinear(&tex, uv);
        }
        for (int k = 0; k < 50; k++) {
            real u = between(999, 1001), v = between(-1001, -999);
            expect_bilinear(&tex, (mesh_uv){u, v});
        }
    }
}

/* ---- the sphere's (u, v) --------------------------------------------------------------------- */

/* The course's convention (measured, sphere_uv.h): +z is u = 1/2, +x is
 * u = 3/4, -x is 1/4; the poles are v = 1 (+y) and 0; the equator 1/2; a
 * sphere far from the origin gives the same. */
static void test_sphere_uv(void **state)
{
    (void)state;
    vec3 center = {-37.25, 12.5, 53.125};
    real radius = 2.5;
    struct {
        vec3 d;
        double u, v;
    } cases[] = {
        {{0, 0, 1}, 0.5, 0.5},      {{1, 0, 0}, 0.75, 0.5},     {{-1, 0, 0}, 0.25, 0.5},
        {{0, 1, 0}, -1, 1},         {{0, -1, 0}, -1, 0},        {{0, 0.5, 0.8660254037844386}, 0.5, 2.0 / 3},
        {{0.7071067811865476, -0.7071067811865476, 0}, 0.75, 0.25},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        mesh_uv uv = sphere_uv(center, radius, vec3_add(center, vec3_scale(cases[k].d, radius)));
        if (cases[k].u >= 0) /* (u is any value at a pole) */
            assert_close(cases[k].u, uv.u, TOL(60));
        assert_close(cases[k].v, uv.v, 1e3 * REAL_EPSILON); /* asin near the poles: sqrt of rounding */
    }
    /* u runs once around: just either side of -z is u near 0 and near 1 */
    mesh_uv left = sphere_uv(center, radius, vec3_add(center, vec3_make((real)-0.01, 0, -radius)));
    mesh_uv right = sphere_uv(center, radius, vec3_add(center, vec3_make((real)0.01, 0, -radius)));
    assert_true(left.u < 0.01 && right.u > 0.99);
}

/* ---- the shading normal -------------------------------------------------------------------- */

/* The values interpolate_vec3's mistakes give for the unit normals N at
 * (beta, gamma), normalized: what vertex_normal gives with each. */
static void normal_mistakes(suspect_vec3 mistakes[INTERPOLATE_MISTAKES], const vec3 N[3], real beta, real gamma)
{
    interpolate_mistakes(mistakes, N[0], N[1], N[2], beta, gamma);
    for (int k = 0; k < INTERPOLATE_MISTAKES; k++)
        if (vec3_length_squared(mistakes[k].value) > 0)
            mistakes[k].value = vec3_normalize(mistakes[k].value);
}

static const char *const normal_hint = "vertex_normal (given) normalizes interpolate_vec3 of the corner normals: "
                                       "interpolate_vec3 must give (1 - beta - gamma) n_a + beta n_b + gamma n_c "
                                       "(test_interpolate_vertices_edges names its mistakes)";

/* vertex_normal(m, f, beta, gamma) has a normal when `has` says so, and
 * then it is `expected` within `tolerance`.  vertex_normal is given, so a
 * failure names interpolate_vec3's mistake whose normal was got. */
static void expect_vertex_normal(const mesh *m, const mesh_face *f, real beta, real gamma, int has, vec3 expected,
                                 double tolerance)
{
    vec3 N[3], n = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        N[k] = f->vn[k] >= 0 ? m->normals[f->vn[k]] : vec3_make(0, 0, 0);
    int got = vertex_normal(m, f, beta, gamma, &n);
    suspect_vec3 mistakes[INTERPOLATE_MISTAKES], named[INTERPOLATE_MISTAKES];
    normal_mistakes(mistakes, N, beta, gamma);
    const char *input = describe("vertex_normal(corner normals %s%s)", interpolate_input(N[0], N[1], N[2], beta, gamma),
                                 f->vn[0] < 0 || f->vn[1] < 0 || f->vn[2] < 0 ? ", a corner without vn" : "");
    const char *why = has ? "a corner's normal, or a blend of unit normals that do not cancel, is a normal; the blend "
                            "came out the zero vector or not finite: check interpolate_vec3 "
                            "(test_interpolate_vertices_edges names its mistakes)"
                          : f->vn[0] < 0 || f->vn[1] < 0 || f->vn[2] < 0
                                ? "a face with a corner without a normal is shaded flat (vertex_normal is given)"
                                : matching_once(named, mistakes, INTERPOLATE_MISTAKES, n, TOL(8))
                                      ? named[0].mistake
                                      : "the corner normals cancel here, so their blend is the zero vector and the face "
                                        "is shaded flat; interpolate_vec3 gave another blend: A = (1 - beta - gamma) "
                                        "A_a + beta A_b + gamma A_c";
    /* n is written only with a normal */
    assert_close_why(
        has, got, 0,
        describe("%s: 1 with a normal, 0 without%s", input,
                 got ? describe("; got n = (%.9g, %.9g, %.9g)", (double)n.x, (double)n.y, (double)n.z) : ""),
        why, NULL, 0);
    if (has)
        assert_vec3_why(expected, n, tolerance, input, normal_hint, mistakes, INTERPOLATE_MISTAKES);
}

/* The interpolated normal at a face's corners is the corner's normal, in
 * between the normalized blend; a face with a corner without vn has none,
 * nor has a point where the corner normals cancel. */
static void test_vertex_normal(void **state)
{
    (void)state;
    vec3 normals[3] = {vec3_normalize(vec3_make(1, 2, 3)), vec3_normalize(vec3_make(-2, 1, 0.5)),
                       vec3_normalize(vec3_make(0.3, -0.2, 1))};
    mesh m = {.normals = normals, .n_normals = 3};
    mesh_face f = {{0, 1, 2}, {-1, -1, -1}, {0, 1, 2}};
    for (int corner = 0; corner < 3; corner++)
        expect_vertex_normal(&m, &f, corner == 1, corner == 2, 1, normals[corner], TOL(4));
    for (int k = 0; k < 100; k++) {
        real beta = between(0, 1), gamma = between(0, 1 - beta), alpha = 1 - beta - gamma;
        vec3 blend = vec3_add(vec3_add(vec3_scale(normals[0], alpha), vec3_scale(normals[1], beta)),
                              vec3_scale(normals[2], gamma));
        expect_vertex_normal(&m, &f, beta, gamma, 1, vec3_normalize(blend), TOL(8));
    }
    mesh_face flat = {{0, 1, 2}, {-1, -1, -1}, {0, -1, 2}};
    expect_vertex_normal(&m, &flat, (real)0.2, (real)0.3, 0, vec3_make(0, 0, 0), 0);
    vec3 opposite[3] = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}}; /* cancel at beta = 1/2, gamma = 0 */
    mesh cancel = {.normals = opposite, .n_normals = 3};
    expect_vertex_normal(&cancel, &f, (real)0.5, 0, 0, vec3_make(0, 0, 0), 0);
}

/* The geometric normal decides the side; a mirror direction below the
 * surface is flipped above it, and the normal returned reflects v to the
 * flipped direction exactly; one above the surface changes nothing. */
static void test_mirror_above(void **state)
{
    (void)state;
    vec3 n_g = vec3_normalize(vec3_make(1, 4, -2));
    assert_vec3_close(vec3_neg(n_g), shading_normal(vec3_neg(n_g), vec3_neg(n_g)), 0);
    assert_vec3_close(n_g, shading_normal(vec3_neg(n_g), n_g), 0);
    int flipped = 0;
    for (int k = 0; k < 2000; k++) {
        vec3 v = vec3_normalize(random_vec3(1)), n_s = vec3_normalize(vec3_add(n_g, random_vec3(0.8)));
        if (vec3_dot(v, n_g) < 0)
            v = vec3_neg(v);
        n_s = shading_normal(n_s, n_g);
        vec3 r = vec3_sub(vec3_scale(n_s, 2 * vec3_dot(n_s, v)), v);
        vec3 n = mirror_above(n_s, n_g, v);
        vec3 r_new = reflect(vec3_neg(v), n);
        assert_close(1, vec3_length(n), TOL(4));
        assert_true(vec3_dot(r_new, n_g) >= -TOL(8));
        if (vec3_dot(r, n_g) >= 0) {
            assert_vec3_close(n_s, n, 0);
        } else {
            flipped++;
            vec3 r_up = vec3_sub(r, vec3_scale(n_g, 2 * vec3_dot(r, n_g)));
            assert_vec3_close(r_up, r_new, TOL(16));
        }
    }
    assert_true(flipped > 100); /* the case did occur */
}

/* ---- shading through the stage ------------------------------------------------------------------ */

/* Chapter 10's stage: its shade function with the knobs' defaults, over the linear scan. */
static const shading_stage stage10 = {.name = "10_interpolation", .shade = shade_interp};

/* Traces one ray with chapter 10's stage through desc. */
static color trace_10(const scene *desc, ray r, uint64_t *rays)
{
    char err[256] = "";
    shading_view *view = shading_prepare(&stage10, desc, SPHERE_ROBUST, TRIANGLE_WATERTIGHT, err, sizeof err);
    if (!view)
        fail_msg("%s", err);
    color c = trace(&view->tr, r, 0, REAL_INFINITY, 0, rays);
    shading_release(view);
    return c;
}

/* A mesh of one triangle (a, b, c) with room for n_normals normals and n_uvs
 * texture coordinates, which the caller fills in with the face's vn and vt
 * (-1 until then); the scene it is added to frees it. */
static mesh one_triangle_mesh(vec3 a, vec3 b, vec3 c, int n_normals, int n_uvs)
{
    mesh m = {.n_positions = 3, .n_normals = n_normals, .n_uvs = n_uvs, .n_faces = 1};
    m.positions = malloc(sizeof *m.positions * 3);
    m.normals = n_normals ? malloc(sizeof *m.normals * (size_t)n_normals) : NULL;
    m.uvs = n_uvs ? malloc(sizeof *m.uvs * (size_t)n_uvs) : NULL;
    m.faces = malloc(sizeof *m.faces);
    assert_non_null(m.positions);
    assert_true(!n_normals || m.normals);
    assert_true(!n_uvs || m.uvs);
    assert_non_null(m.faces);
    m.positions[0] = a, m.positions[1] = b, m.positions[2] = c;
    m.faces[0] = (mesh_face){{0, 1, 2}, {-1, -1, -1}, {-1, -1, -1}};
    return m;
}

/* One triangle far from the origin with three different vertex normals, lit
 * by one light without shadows in the way: the radiance at a point inside is
 * k_d max(0, n . l) I / r^2 with n the INTERPOLATED normal at the hit's
 * (beta, gamma), not the flat one; RGBNormals shows (n + 1) / 2 of it.  Seen
 * and lit from below, the Lambertian triangle shades with -n, turned to the
 * viewer's side. */
static void test_smooth_shading(void **state)
{
    (void)state;
    vec3 offset = {-37.25, 12.5, 53.125};
    for (int run = 0; run < 3; run++) {
        const int rgb = run == 1;
        const real side = run == 2 ? -1 : 1; /* the viewer and the light above (+z) or below the triangle */
        scene desc;
        scene_init(&desc);
        vec3 a = vec3_add(offset, vec3_make(0, 0, 0)), b = vec3_add(offset, vec3_make(3, 0.5, 0)),
             c = vec3_add(offset, vec3_make(0.5, 3, 0.25));
        mesh m = one_triangle_mesh(a, b, c, 3, 0);
        m.normals[0] = vec3_normalize(vec3_make(-0.5, -0.4, 1)), m.normals[1] = vec3_normalize(vec3_make(0.6, 0, 1));
        m.normals[2] = vec3_normalize(vec3_make(0, 0.7, 1));
        m.faces[0].vn[0] = 0, m.faces[0].vn[1] = 1, m.faces[0].vn[2] = 2;
        int mk = scene_add_mesh(&desc, m);
        scene_shader s = scene_default_shader(rgb ? SHADER_RGB_NORMALS : SHADER_LAMBERTIAN);
        s.diffuse_color = color_make((real)0.3, (real)0.2, (real)0.1);
        int sk = scene_add_shader(&desc, s);
        scene_add_surface(&desc, (scene_surface){.kind = SURFACE_MESH, .shader = sk, .mesh = mk});
        scene_light light = {.position = vec3_add(offset, vec3_make(1, 1, 6 * side)), .intensity = {20, 20, 20}};
        scene_add_light(&desc, light);
        real beta = (real)0.3, gamma = (real)0.45, alpha = 1 - beta - gamma;
        vec3 p = vec3_add(vec3_add(vec3_scale(a, alpha), vec3_scale(b, beta)), vec3_scale(c, gamma));
        vec3 eye = vec3_add(p, vec3_make((real)0.4, (real)-0.3, 5 * side));
        uint64_t rays[RAY_KINDS] = {0};
        color L = trace_10(&desc, (ray){eye, vec3_sub(p, eye)}, rays);
        vec3 n = vec3_normalize(vec3_add(vec3_add(vec3_scale(m.normals[0], alpha), vec3_scale(m.normals[1], beta)),
                                         vec3_scale(m.normals[2], gamma)));
        const vec3 n_raw = n; /* RGBNormals shows the interpolated normal as it is */
        n = vec3_scale(n, side);  /* Lambert: on the viewer's side of the face */
        /* The hit's beta and gamma are computed from coordinates of size |p| ~ 66
         * over edges of size ~3: ~100 roundings relative; n and the cosine
         * inherit that; a margin of 20. */
        double tol = 2e3 * REAL_EPSILON;
        /* what interpolate_vec3's mistakes give: their normal, on the viewer's side of the face */
        vec3 n_g = vec3_normalize(vec3_cross(vec3_sub(b, a), vec3_sub(c, a)));
        if (vec3_dot(n_g, vec3_sub(eye, p)) < 0)
            n_g = vec3_neg(n_g);
        suspect_vec3 normals[INTERPOLATE_MISTAKES];
        normal_mistakes(normals, m.normals, beta, gamma);
        const char *input = describe("chapter 10's stage: a triangle with corner normals %s, the eye ray to the point "
                                     "at (beta, gamma)%s, %s",
                                     interpolate_input(m.normals[0], m.normals[1], m.normals[2], beta, gamma),
                                     side < 0 ? " from below, the light below too" : "",
                                     rgb ? "RGBNormals: (n + 1) / 2" : "Lambertian: k_d I max(0, n . l) / r^2");
        const char *hint = side < 0 ? "the shading normal is vertex_normal's, turned to the side of the normal that "
                                      "faces the viewer, sp->n (README, \"Interpolated normals\")"
                                    : "the shading normal is vertex_normal's (given): interpolate_vec3 of the corner "
                                      "normals, normalized; interpolate_vec3 must give (1 - beta - gamma) n_a + beta "
                                      "n_b + gamma n_c";
        if (rgb) {
            suspect_vec3 shown[INTERPOLATE_MISTAKES];
            for (int k = 0; k < INTERPOLATE_MISTAKES; k++) {
                vec3 n_k = shading_normal(normals[k].value, n_g);
                shown[k] = (suspect_vec3){vec3_scale(vec3_add(n_k, vec3_make(1, 1, 1)), (real)0.5), normals[k].mistake};
            }
            assert_vec3_why(vec3_scale(vec3_add(n_raw, vec3_make(1, 1, 1)), (real)0.5), vec3_make(L.r, L.g, L.b), tol,
                            input, hint, shown, INTERPOLATE_MISTAKES);
        } else {
            vec3 to_light = vec3_sub(light.position, p);
            real r2 = vec3_length_squared(to_light);
            vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));
            real cosine = vec3_dot(n, l);
            suspect red[INTERPOLATE_MISTAKES], blue[INTERPOLATE_MISTAKES];
            for (int k = 0; k < INTERPOLATE_MISTAKES; k++) {
                double cos_k = fmax(0, (double)vec3_dot(shading_normal(normals[k].value, n_g), l));
                red[k] = (suspect){0.3 * 20 * cos_k / r2, normals[k].mistake};
                blue[k] = (suspect){0.1 * 20 * cos_k / r2, normals[k].mistake};
            }
            assert_close_why(0.3 * 20 * cosine / r2, L.r, tol * 0.3 * 20 / r2, describe("%s: red", input), hint, red,
                             INTERPOLATE_MISTAKES);
            assert_close_why(0.1 * 20 * cosine / r2, L.b, tol * 0.1 * 20 / r2, describe("%s: blue", input), hint, blue,
                             INTERPOLATE_MISTAKES);
            assert_close_why(1, rays[RAY_SHADOW], 0, describe("%s: shadow rays cast", input),
                             "one shadow ray to the one light (chapter 06's shading, given here)", NULL, 0);
        }
        scene_free(&desc);
    }

    /* A matte triangle in a plane z = const whose corner normals are all N = (1, 0, 0.3) / |(1, 0, 0.3)|, seen
     * at a grazing angle, v = (-1, 0, 0.2) / |(-1, 0, 0.2)|: the mirror direction about N, 2 (N . v) N - v,
     * points below the face, but a matte point casts no mirror ray and keeps N; the light 3 straight above
     * the point: L = k_d I (N . l) / r^2 = 0.5 * 9 * 0.3 / |(1, 0, 0.3)| / 9.  N is interpolated from equal
     * normals, the point is ~66 from the origin: a few hundred roundings at most, 1e3 REAL_EPSILON. */
    scene desc;
    scene_init(&desc);
    mesh m = one_triangle_mesh(offset, vec3_add(offset, vec3_make(4, 0, 0)), vec3_add(offset, vec3_make(0, 4, 0)),
                               1, 0);
    m.normals[0] = vec3_normalize(vec3_make(1, 0, (real)0.3));
    m.faces[0].vn[0] = m.faces[0].vn[1] = m.faces[0].vn[2] = 0;
    int mk = scene_add_mesh(&desc, m);
    scene_shader matte = scene_default_shader(SHADER_LAMBERTIAN);
    matte.diffuse_color = color_make((real)0.5, (real)0.5, (real)0.5);
    const int sk = scene_add_shader(&desc, matte);
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_MESH, .shader = sk, .mesh = mk});
    const vec3 p = vec3_add(offset, vec3_make((real)1.2, (real)0.8, 0));
    scene_add_light(&desc, (scene_light){.position = vec3_add(p, vec3_make(0, 0, 3)), .intensity = {9, 9, 9}});
    uint64_t rays[RAY_KINDS] = {0};
    const color L = trace_10(&desc, (ray){vec3_add(p, vec3_make(-5, 0, 1)), vec3_make(5, 0, -1)}, rays);
    assert_close_why(0.5 * 0.3 / sqrt(1.09), L.r, 1e3 * REAL_EPSILON,
                     "a matte smooth triangle, every corner normal (1, 0, 0.3) normalized, seen at a grazing angle "
                     "whose mirror direction about that normal is below the face, the light straight above",
                     "only a point that casts mirror rays (a mirror coefficient, or glass) has its normal turned "
                     "to keep the mirror direction above the face; a matte point keeps n_s (README, \"A mirror "
                     "direction below the surface\")",
                     NULL, 0);
    scene_free(&desc);
}

/* A textured Lambertian sphere: the diffuse colour is the texel at the
 * point's (u, v) (sphere_uv), the shader's own diffuseColor is not used. */
static void test_textured_sphere(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    texture_image img;
    assert_int_equal(0, globe_texture(&img, 16, 8, 2));
    int tk = scene_add_texture(&desc, (scene_texture){.kind = TEXTURE_REPEAT, .image = img});
    scene_shader s = scene_default_shader(SHADER_LAMBERTIAN);
    s.diffuse_color = color_make(1, 0, 1); /* replaced by the texture */
    s.texture = tk;
    int sk = scene_add_shader(&desc, s);
    vec3 center = {-37.25, 12.5, 53.125};
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = sk, .center = center, .radius = 2});
    vec3 d = vec3_normalize(vec3_make((real)0.3, (real)0.35, 1)); /* the point's direction from the centre */
    vec3 p = vec3_add(center, vec3_scale(d, 2));
    scene_light light = {.position = vec3_add(p, vec3_scale(d, 3)), .intensity = {9, 9, 9}};
    scene_add_light(&desc, light);
    uint64_t rays[RAY_KINDS] = {0};
    vec3 eye = vec3_add(p, vec3_scale(d, 10));
    color L = trace_10(&desc, (ray){eye, vec3_sub(p, eye)}, rays);
    /* the texel by hand: u = 1/2 + atan2(x, z) / 2 pi, v = 1/2 + asin(y) / pi;
     * column (u W + 1/2), row ((1 - v) H + 1/2), neither near a texel's edge */
    double u = 0.5 + atan2(0.3, 1.0) / (2 * pi), v = 0.5 + asin(0.35 / sqrt(0.09 + 0.1225 + 1)) / pi;
    int x = (int)(u * 16 + 0.5) % 16, y = (int)((1 - v) * 8 + 0.5) % 8;
    const unsigned char *texel = desc.textures[tk].image.rgb + (y * 16 + x) * 3;
    /* the light straight above the point: cos = 1, r = 3, I / r^2 = 1 */
    assert_vec3_why(vec3_make((real)(texel[0] / 255.0), (real)(texel[1] / 255.0), (real)(texel[2] / 255.0)),
                    vec3_make(L.r, L.g, L.b), 1e3 * REAL_EPSILON,
                    describe("a textured sphere lit straight above the point at u = %.9g, v = %.9g: texel (%d, %d) of "
                             "16 x 8",
                             u, v, x, y),
                    "the diffuse colour is the texel texture_nearest reads at the sphere's (u, v): column (long "
                    "long)(u W + 1/2), row (long long)((1 - v) H + 1/2) (test_nearest names its mistakes)",
                    NULL, 0);
    assert_false(texel[0] == texel[1] && texel[1] == texel[2]); /* a coloured texel, not magenta, not grey */
    scene_free(&desc);

    /* A textured mesh triangle in a plane z = const (normal +z), corners a, b = a + (4, 0, 0), c = a + (0, 4, 0)
     * with texture coordinates (0.1, 0.1), (0.9, 0.1), (0.1, 0.9), hit at beta 0.55, gamma 0.2: (u, v) =
     * (0.1 + 0.8 beta, 0.1 + 0.8 gamma) = (0.54, 0.26), texel column (long long)(0.54 16 + 1/2) = 9, row
     * (long long)(0.74 8 + 1/2) = 6; beta and gamma swapped would read (0.26, 0.54), texel (4, 4).  The hit's
     * (beta, gamma) carry roundings of coordinates ~60 over edges of 4, far below the 0.1 of a texel's edge. */
    scene_init(&desc);
    assert_int_equal(0, globe_texture(&img, 16, 8, 2));
    s.texture = scene_add_texture(&desc, (scene_texture){.kind = TEXTURE_REPEAT, .image = img});
    sk = scene_add_shader(&desc, s);
    mesh m = one_triangle_mesh(center, vec3_add(center, vec3_make(4, 0, 0)), vec3_add(center, vec3_make(0, 4, 0)),
                               0, 3);
    m.uvs[0] = (mesh_uv){(real)0.1, (real)0.1}, m.uvs[1] = (mesh_uv){(real)0.9, (real)0.1};
    m.uvs[2] = (mesh_uv){(real)0.1, (real)0.9};
    m.faces[0].vt[0] = 0, m.faces[0].vt[1] = 1, m.faces[0].vt[2] = 2;
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_MESH, .shader = sk, .mesh = scene_add_mesh(&desc, m)});
    p = vec3_add(center, vec3_make((real)(4 * 0.55), (real)(4 * 0.2), 0));
    scene_add_light(&desc, (scene_light){.position = vec3_add(p, vec3_make(0, 0, 3)), .intensity = {9, 9, 9}});
    eye = vec3_add(p, vec3_make((real)0.5, (real)0.25, 10));
    L = trace_10(&desc, (ray){eye, vec3_sub(p, eye)}, rays);
    texel = desc.textures[0].image.rgb + (6 * 16 + 9) * 3;
    const unsigned char *swapped = desc.textures[0].image.rgb + (4 * 16 + 4) * 3;
    assert_false(texel[0] == swapped[0] && texel[1] == swapped[1] && texel[2] == swapped[2]);
    /* the light straight above the point: cos = 1, r = 3, I / r^2 = 1 */
    assert_vec3_why(vec3_make((real)(texel[0] / 255.0), (real)(texel[1] / 255.0), (real)(texel[2] / 255.0)),
                    vec3_make(L.r, L.g, L.b), 1e3 * REAL_EPSILON,
                    "a textured mesh triangle, corner texture coordinates (0.1, 0.1), (0.9, 0.1), (0.1, 0.9), lit "
                    "straight above the point at beta 0.55, gamma 0.2: texel (9, 6) of 16 x 8",
                    "the point's (u, v) is interpolate_uv of its face's corner coordinates (vt) with the hit's "
                    "beta and gamma, in the order of the face's corners (README, \"The shade function\")",
                    NULL, 0);
    /* The face with texture coordinates at its first corner only (an OBJ face "f 1/1 2 3"): no (u, v) at
     * the point, the shader's own diffuse colour (1, 0, 1) */
    desc.meshes[0].faces[0].vt[1] = desc.meshes[0].faces[0].vt[2] = -1;
    L = trace_10(&desc, (ray){eye, vec3_sub(p, eye)}, rays);
    assert_vec3_why(vec3_make(1, 0, 1), vec3_make(L.r, L.g, L.b), 1e3 * REAL_EPSILON,
                    "the same triangle, its face with texture coordinates at the first corner only, lit straight "
                    "above the point",
                    "a face has (u, v) only when every one of its corners has texture coordinates (vt >= 0); "
                    "without, the point keeps the shader's diffuse colour (README, \"The shade function\")",
                    NULL, 0);
    scene_free(&desc);
}

/* The built-in scene renders through interpolation and textures: the flat
 * sphere and the smooth one differ only in their shading normals, so two
 * rays through the same triangle of each give different radiance, and the
 * smooth one's follows the sphere's own normal. */
static void test_builtin_scene_smooth_and_flat(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    assert_int_equal(0, interp_scene(&desc));
    char err[256] = "";
    shading_view *view = shading_prepare(&stage10, &desc, SPHERE_ROBUST, TRIANGLE_WATERTIGHT, err, sizeof err);
    if (!view)
        fail_msg("%s", err);
    /* the same point, relative to each sphere's centre, seen from in front */
    vec3 rel = vec3_normalize(vec3_make((real)0.41, (real)0.23, 1));
    color L[2];
    for (int k = 0; k < 2; k++) {
        vec3 centre = vec3_make(k == 0 ? (real)-2.3 : 0, 0, 0);
        vec3 target = vec3_add(centre, vec3_scale(rel, (real)0.9));
        vec3 eye = vec3_add(centre, vec3_scale(rel, 8));
        uint64_t rays[RAY_KINDS] = {0};
        L[k] = trace(&view->tr, (ray){eye, vec3_sub(target, eye)}, 0, REAL_INFINITY, 0, rays);
    }
    shading_release(view);
    scene_free(&desc);
    assert_true_why(
        fabs((double)(L[0].r - L[1].r)) + fabs((double)(L[0].g - L[1].g)) > 1e-3,
        "chapter 10's built-in scene: a ray to the same point of the flat sphere and of the smooth one (0.9 "
        "along (0.41, 0.23, 1) from each centre)\n    expected different radiance (|r - r'| + |g - g'| above "
        "1e-3: the smooth sphere is shaded with its interpolated normal)\n    got      flat (%.9g, %.9g), "
        "smooth (%.9g, %.9g)\n    likely mistake: the two spheres shaded alike: the smooth one's shading "
        "normal is vertex_normal's, the normalized (1 - beta - gamma) n_a + beta n_b + gamma n_c, and its k_d "
        "the texel at its interpolated (u, v) (README, \"Interpolated normals\" and \"The shade function\")",
        (double)L[0].r, (double)L[0].g, (double)L[1].r, (double)L[1].g);
}

static const graded_test tests[] = {
    GRADED(test_interpolate_vertices_edges, 2),
    GRADED(test_interpolate_random, 2),
    GRADED(test_interpolate_uv, 1),
    GRADED(test_texel_index_repeat, 2),
    GRADED(test_texel_index_clamp, 2),
    GRADED(test_nearest, 3),
    GRADED(test_nearest_quirk, 1),
    GRADED(test_bilinear, 3),
    GRADED(test_bilinear_random, 2),
    GRADED(test_vertex_normal, 2),
    GRADED(test_smooth_shading, 3),
    GRADED(test_textured_sphere, 2),
    GRADED(test_sphere_uv, 0),                     /* handed out complete: no points */
    GRADED(test_mirror_above, 0),                  /* handed out complete: no points */
    GRADED(test_builtin_scene_smooth_and_flat, 0), /* handed out complete: no points */
};

SUITE_MAIN("10_interpolation", tests)
