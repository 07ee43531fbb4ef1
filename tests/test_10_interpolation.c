/* Chapter 10: barycentric interpolation, texture lookups (wrap, clamp, nearest,
 * bilinear), the interpolated shading normal, textured shading. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "05_lambert/shading_stage.h"
#include "08_mirrors/mirror.h"
#include "10_interpolation/interp_scene.h"
#include "10_interpolation/interp_stage.h"
#include "10_interpolation/interpolate.h"
#include "10_interpolation/shading_normal.h"
#include "10_interpolation/sphere_mesh.h"
#include "10_interpolation/sphere_uv.h"
#include "10_interpolation/texture.h"
#include "scene_build.h"
#include "suite.h"

/* A few roundings of values of size about 1 (see test_05_lambert.c). */
#define TOL(size) (32 * REAL_EPSILON * (size))

static const double pi = 3.14159265358979323846;

/* Random numbers (a fixed seed: the same numbers on every run). */
static unsigned long rng = 424242;
static double uniform(void)
{
    rng = rng * 6364136223846793005UL + 1442695040888963407UL;
    return (double)((rng >> 11) & ((1UL << 53) - 1)) / (double)(1UL << 53);
}
static real between(double lo, double hi) { return (real)(lo + (hi - lo) * uniform()); }
static vec3 random_vec3(double size)
{
    return vec3_make(between(-size, size), between(-size, size), between(-size, size));
}

/* ---- barycentric interpolation ---------------------------------------------------------------- */

/* At the vertices the attribute is the vertex's own, exactly (weights 1, 0,
 * 0); at an edge's midpoint the mean of its two ends; at the centroid the
 * mean of all three. */
static void test_interpolate_vertices_edges(void **state)
{
    (void)state;
    vec3 A_a = {37.25, -12.5, 53.125}, A_b = {-3.75, 8.5, 0.625}, A_c = {1e3, -7e2, 2.5e2};
    assert_vec3_close(A_a, interpolate_vec3(A_a, A_b, A_c, 0, 0), 0);
    assert_vec3_close(A_b, interpolate_vec3(A_a, A_b, A_c, 1, 0), 0);
    assert_vec3_close(A_c, interpolate_vec3(A_a, A_b, A_c, 0, 1), 0);
    vec3 mid_ab = vec3_scale(vec3_add(A_a, A_b), (real)0.5), mid_bc = vec3_scale(vec3_add(A_b, A_c), (real)0.5);
    assert_vec3_close(mid_ab, interpolate_vec3(A_a, A_b, A_c, 0.5, 0), TOL(60));
    assert_vec3_close(mid_bc, interpolate_vec3(A_a, A_b, A_c, 0.5, 0.5), TOL(1000));
    vec3 centroid = vec3_scale(vec3_add(vec3_add(A_a, A_b), A_c), (real)(1.0 / 3));
    assert_vec3_close(centroid, interpolate_vec3(A_a, A_b, A_c, (real)(1.0 / 3), (real)(1.0 / 3)), TOL(1000));
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
        assert_vec3_close(point, interpolate_vec3(a, b, c, beta, gamma), TOL(200));
        vec3 A[3] = {random_vec3(1), random_vec3(1), random_vec3(1)};
        vec3 B[3] = {random_vec3(1), random_vec3(1), random_vec3(1)};
        vec3 sum = vec3_add(interpolate_vec3(A[0], A[1], A[2], beta, gamma),
                            interpolate_vec3(B[0], B[1], B[2], beta, gamma));
        vec3 of_sum = interpolate_vec3(vec3_add(A[0], B[0]), vec3_add(A[1], B[1]), vec3_add(A[2], B[2]), beta, gamma);
        assert_vec3_close(sum, of_sum, TOL(8));
    }
}

/* Texture coordinates interpolate the same way (u and v each). */
static void test_interpolate_uv(void **state)
{
    (void)state;
    mesh_uv a = {0.125, 0.75}, b = {2.5, -1.25}, c = {-0.375, 0.5};
    mesh_uv at_b = interpolate_uv(a, b, c, 1, 0);
    assert_close(2.5, at_b.u, 0);
    assert_close(-1.25, at_b.v, 0);
    for (int k = 0; k < 100; k++) {
        real beta = between(0, 1), gamma = between(0, 1 - beta), alpha = 1 - beta - gamma;
        mesh_uv uv = interpolate_uv(a, b, c, beta, gamma);
        assert_close(alpha * a.u + beta * b.u + gamma * c.u, uv.u, TOL(4));
        assert_close(alpha * a.v + beta * b.v + gamma * c.v, uv.v, TOL(4));
    }
}

/* ---- texel indices: repeat and clamp ------------------------------------------------------------- */

/* RepeatTexture: i mod n in [0, n), negative i included (-1 is the last
 * column), far beyond the image too; against i - n floor(i / n). */
static void test_texel_index_repeat(void **state)
{
    (void)state;
    assert_int_equal(0, texel_index(TEXTURE_REPEAT, 0, 7));
    assert_int_equal(6, texel_index(TEXTURE_REPEAT, 6, 7));
    assert_int_equal(0, texel_index(TEXTURE_REPEAT, 7, 7));
    assert_int_equal(6, texel_index(TEXTURE_REPEAT, -1, 7));
    assert_int_equal(0, texel_index(TEXTURE_REPEAT, -7, 7));
    assert_int_equal(0, texel_index(TEXTURE_REPEAT, 12345, 1));
    for (long long i = -1000; i <= 1000; i += 37)
        for (int n = 1; n < 300; n += 41) {
            long long expected = i - n * (long long)floor((double)i / n);
            assert_int_equal(expected, texel_index(TEXTURE_REPEAT, i, n));
        }
    assert_int_equal(1099511627776LL % 256, texel_index(TEXTURE_REPEAT, 1099511627776LL, 256));
    assert_int_equal(256 - 1099511627777LL % 256, texel_index(TEXTURE_REPEAT, -1099511627777LL, 256));
}

/* ClampTexture: indices before the image read its first texel, beyond it its last. */
static void test_texel_index_clamp(void **state)
{
    (void)state;
    assert_int_equal(0, texel_index(TEXTURE_CLAMP, -1, 7));
    assert_int_equal(0, texel_index(TEXTURE_CLAMP, -1099511627776LL, 7));
    assert_int_equal(3, texel_index(TEXTURE_CLAMP, 3, 7));
    assert_int_equal(6, texel_index(TEXTURE_CLAMP, 6, 7));
    assert_int_equal(6, texel_index(TEXTURE_CLAMP, 7, 7));
    assert_int_equal(6, texel_index(TEXTURE_CLAMP, 1099511627776LL, 7));
    assert_int_equal(0, texel_index(TEXTURE_CLAMP, 5, 1));
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

/* Which texel a colour of `numbered` is: column and row. */
static void assert_texel(int x, int y, color c)
{
    assert_close(10 * x / 255.0, c.r, TOL(1));
    assert_close(10 * y / 255.0, c.g, TOL(1));
    assert_close(7 / 255.0, c.b, TOL(1));
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
                    assert_texel(x, y, texture_nearest(&tex, uv));
                }
            }
        /* v = 1 is the top row, v just above 0 the bottom row */
        assert_texel(0, 0, texture_nearest(&tex, (mesh_uv){0, 1}));
        assert_texel(2, TH - 1, texture_nearest(&tex, (mesh_uv){(real)(2.0 / TW), (real)0.2}));
        /* beyond the right edge: column 0 again, or the last column */
        assert_texel(kind == TEXTURE_REPEAT ? 1 : TW - 1, 1,
                     texture_nearest(&tex, (mesh_uv){(real)(1 + 1.1 / TW), (real)(1 - 1.0 / TH)}));
        /* u + 3, v - 2 read what u, v read when repeated */
        if (kind == TEXTURE_REPEAT)
            assert_texel(3, 2, texture_nearest(&tex, (mesh_uv){(real)(3 + 3.2 / TW), (real)(-2 + 1 - 2.1 / TH)}));
        else
            assert_texel(TW - 1, TH - 1,
                         texture_nearest(&tex, (mesh_uv){(real)(3 + 3.2 / TW), (real)(-2 + 1 - 2.1 / TH)}));
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
    assert_texel(0, 1, texture_nearest(&tex, (mesh_uv){(real)(-0.3 / TW), v}));
    assert_texel(0, 1, texture_nearest(&tex, (mesh_uv){(real)(-0.8 / TW), v}));
    assert_texel(0, 1, texture_nearest(&tex, (mesh_uv){(real)(-1.4 / TW), v}));
    assert_texel(TW - 1, 1, texture_nearest(&tex, (mesh_uv){(real)(-1.7 / TW), v}));
    assert_texel(TW - 1, 1, texture_nearest(&tex, (mesh_uv){(real)(-2.4 / TW), v}));
    assert_texel(TW - 2, 1, texture_nearest(&tex, (mesh_uv){(real)(-2.6 / TW), v}));
    /* rows the same way: v above 1 + 1/(2H) */
    assert_texel(2, 0, texture_nearest(&tex, (mesh_uv){(real)(2.0 / TW), (real)(1 + 1.2 / TH)}));
    assert_texel(2, TH - 1, texture_nearest(&tex, (mesh_uv){(real)(2.0 / TW), (real)(1 + 1.7 / TH)}));
    /* NaN and huge coordinates read something, without undefined behaviour */
    assert_texel(0, 0, texture_nearest(&tex, (mesh_uv){(real)NAN, (real)1}));
    scene_texture clamp = numbered(TEXTURE_CLAMP);
    assert_texel(TW - 1, 0, texture_nearest(&clamp, (mesh_uv){(real)1e30, (real)1e30}));
    assert_texel(0, TH - 1, texture_nearest(&clamp, (mesh_uv){(real)-1e30, (real)-1e30}));
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
        color c = texture_bilinear(&tex, (mesh_uv){(real)(x / TW), (real)(1 - y / TH)});
        assert_close(10 * x / 255, c.r, TOL(16));
        assert_close(10 * y / 255, c.g, TOL(16));
        assert_close(7 / 255.0, c.b, TOL(4));
    }
    assert_texel(3, 1, texture_bilinear(&tex, (mesh_uv){(real)(3.0 / TW), (real)(1 - 1.0 / TH)}));
    /* half-way between the last column and the one after it */
    real u = (real)((TW - 0.5) / TW), v = (real)(1 - 1.0 / TH);
    color clamped = texture_bilinear(&tex, (mesh_uv){u, v});
    assert_close(10 * (TW - 1) / 255.0, clamped.r, TOL(4));
    scene_texture repeat = numbered(TEXTURE_REPEAT);
    color wrapped = texture_bilinear(&repeat, (mesh_uv){u, v});
    assert_close(0.5 * 10 * (TW - 1) / 255.0, wrapped.r, TOL(4)); /* (last + first) / 2, the first is 0 */
    assert_close(10 / 255.0, wrapped.g, TOL(4));
    /* nearest and bilinear agree at every centre */
    for (int y = 0; y < TH; y++)
        for (int x = 0; x < TW; x++) {
            mesh_uv at = {(real)((double)x / TW), (real)(1 - (double)y / TH)};
            color n = texture_lookup(&repeat, at, TEXTURE_NEAREST), b = texture_lookup(&repeat, at, TEXTURE_BILINEAR);
            assert_vec3_close(vec3_make(n.r, n.g, n.b), vec3_make(b.r, b.g, b.b), TOL(4));
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

/* The interpolated normal at a face's corners is the corner's normal, in
 * between the normalized blend; a face with a corner without vn has none. */
static void test_vertex_normal(void **state)
{
    (void)state;
    vec3 normals[3] = {vec3_normalize(vec3_make(1, 2, 3)), vec3_normalize(vec3_make(-2, 1, 0.5)),
                       vec3_normalize(vec3_make(0.3, -0.2, 1))};
    mesh m = {.normals = normals, .n_normals = 3};
    mesh_face f = {{0, 1, 2}, {-1, -1, -1}, {0, 1, 2}};
    vec3 n;
    for (int corner = 0; corner < 3; corner++) {
        assert_true(vertex_normal(&m, &f, corner == 1, corner == 2, &n));
        assert_vec3_close(normals[corner], n, TOL(4));
    }
    for (int k = 0; k < 100; k++) {
        real beta = between(0, 1), gamma = between(0, 1 - beta), alpha = 1 - beta - gamma;
        vec3 blend = vec3_add(vec3_add(vec3_scale(normals[0], alpha), vec3_scale(normals[1], beta)),
                              vec3_scale(normals[2], gamma));
        assert_true(vertex_normal(&m, &f, beta, gamma, &n));
        assert_vec3_close(vec3_normalize(blend), n, TOL(8));
    }
    mesh_face flat = {{0, 1, 2}, {-1, -1, -1}, {0, -1, 2}};
    assert_false(vertex_normal(&m, &flat, (real)0.2, (real)0.3, &n));
    vec3 opposite[3] = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}}; /* cancel at beta = 1/2, gamma = 0 */
    mesh cancel = {.normals = opposite, .n_normals = 3};
    assert_false(vertex_normal(&cancel, &f, (real)0.5, 0, &n));
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

/* Traces one ray with chapter 10's stage (defaults) through desc. */
static color trace_10(const scene *desc, ray r, uint64_t *rays)
{
    char err[256] = "";
    const shading_stage stage = interp_stage(NULL);
    shading_view *view = shading_prepare(&stage, desc, SPHERE_ROBUST, TRIANGLE_WATERTIGHT, err, sizeof err);
    if (!view)
        fail_msg("%s", err);
    color c = trace(&view->tr, r, 0, REAL_INFINITY, 0, rays);
    shading_release(view);
    return c;
}

/* One triangle far from the origin with three different vertex normals, lit
 * by one light without shadows in the way: the radiance at a point inside is
 * k_d max(0, n . l) I / r^2 with n the INTERPOLATED normal at the hit's
 * (beta, gamma), not the flat one; RGBNormals shows (n + 1) / 2 of it. */
static void test_smooth_shading(void **state)
{
    (void)state;
    vec3 offset = {-37.25, 12.5, 53.125};
    for (int rgb = 0; rgb < 2; rgb++) {
        scene desc;
        scene_init(&desc);
        mesh m = {.n_positions = 3, .n_normals = 3, .n_faces = 1};
        m.positions = malloc(sizeof *m.positions * 3);
        m.normals = malloc(sizeof *m.normals * 3);
        m.faces = malloc(sizeof *m.faces);
        assert_non_null(m.positions);
        assert_non_null(m.normals);
        assert_non_null(m.faces);
        vec3 a = vec3_add(offset, vec3_make(0, 0, 0)), b = vec3_add(offset, vec3_make(3, 0.5, 0)),
             c = vec3_add(offset, vec3_make(0.5, 3, 0.25));
        m.positions[0] = a, m.positions[1] = b, m.positions[2] = c;
        m.normals[0] = vec3_normalize(vec3_make(-0.5, -0.4, 1)), m.normals[1] = vec3_normalize(vec3_make(0.6, 0, 1));
        m.normals[2] = vec3_normalize(vec3_make(0, 0.7, 1));
        m.faces[0] = (mesh_face){{0, 1, 2}, {-1, -1, -1}, {0, 1, 2}};
        int mk = scene_add_mesh(&desc, m);
        scene_shader s = scene_default_shader(rgb ? SHADER_RGB_NORMALS : SHADER_LAMBERTIAN);
        s.diffuse_color = color_make((real)0.3, (real)0.2, (real)0.1);
        int sk = scene_add_shader(&desc, s);
        scene_add_surface(&desc, (scene_surface){.kind = SURFACE_MESH, .shader = sk, .mesh = mk});
        scene_light light = {.position = vec3_add(offset, vec3_make(1, 1, 6)), .intensity = {20, 20, 20}};
        scene_add_light(&desc, light);
        real beta = (real)0.3, gamma = (real)0.45, alpha = 1 - beta - gamma;
        vec3 p = vec3_add(vec3_add(vec3_scale(a, alpha), vec3_scale(b, beta)), vec3_scale(c, gamma));
        vec3 eye = vec3_add(p, vec3_make((real)0.4, (real)-0.3, 5));
        uint64_t rays[RAY_KINDS] = {0};
        color L = trace_10(&desc, (ray){eye, vec3_sub(p, eye)}, rays);
        vec3 n = vec3_normalize(vec3_add(vec3_add(vec3_scale(m.normals[0], alpha), vec3_scale(m.normals[1], beta)),
                                         vec3_scale(m.normals[2], gamma)));
        /* The hit's beta and gamma are computed from coordinates of size |p| ~ 66
         * over edges of size ~3: ~100 roundings relative; n and the cosine
         * inherit that; a margin of 20. */
        double tol = 2e3 * REAL_EPSILON;
        if (rgb) {
            assert_close((n.x + 1) / 2, L.r, tol);
            assert_close((n.y + 1) / 2, L.g, tol);
            assert_close((n.z + 1) / 2, L.b, tol);
        } else {
            vec3 to_light = vec3_sub(light.position, p);
            real r2 = vec3_length_squared(to_light);
            real cosine = vec3_dot(n, vec3_scale(to_light, 1 / real_sqrt(r2)));
            assert_close(0.3 * 20 * cosine / r2, L.r, tol * 0.3 * 20 / r2);
            assert_close(0.1 * 20 * cosine / r2, L.b, tol * 0.1 * 20 / r2);
            assert_int_equal(1, rays[RAY_SHADOW]);
        }
        scene_free(&desc);
    }
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
    assert_close(texel[0] / 255.0, L.r, 1e3 * REAL_EPSILON);
    assert_close(texel[1] / 255.0, L.g, 1e3 * REAL_EPSILON);
    assert_close(texel[2] / 255.0, L.b, 1e3 * REAL_EPSILON);
    assert_false(texel[0] == texel[1] && texel[1] == texel[2]); /* a coloured texel, not magenta, not grey */
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
    const shading_stage stage = interp_stage(NULL);
    shading_view *view = shading_prepare(&stage, &desc, SPHERE_ROBUST, TRIANGLE_WATERTIGHT, err, sizeof err);
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
    assert_true(fabs((double)(L[0].r - L[1].r)) + fabs((double)(L[0].g - L[1].g)) > 1e-3);
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
    GRADED(test_vertex_normal, 2),
    GRADED(test_smooth_shading, 3),
    GRADED(test_textured_sphere, 2),
    GRADED(test_sphere_uv, 0),                     /* handed out complete: no points */
    GRADED(test_mirror_above, 0),                  /* handed out complete: no points */
    GRADED(test_builtin_scene_smooth_and_flat, 0), /* handed out complete: no points */
};

SUITE_MAIN("10_interpolation", tests)
