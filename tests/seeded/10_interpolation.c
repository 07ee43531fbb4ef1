/* Chapter 10's checks of inputs drawn at grading time (tests/answers.h):
 * barycentric interpolation of vectors and texture coordinates, texel
 * indices of each kind (for that kind's test alone), and nearest and bilinear lookups in a texture of
 * texels, all drawn from the grader's seed, against the reference's
 * answers.  An interpolation is a few roundings of its inputs' size
 * (64 REAL_EPSILON of it); a texel index is exact; a lookup is the texel,
 * whose byte / 255 may be rounded otherwise (byte * (1 / 255): 4
 * REAL_EPSILON), or a blend of four texels at weights that carry the
 * rounding of u times the texture's width (64 REAL_EPSILON of the side). */
#include <stdlib.h>

#include "10_interpolation/interpolate.h"
#include "10_interpolation/texture.h"
#include "seeded.h"

static void seeded_interpolate(unsigned long *rng)
{
    for (int k = 0; k < 8; k++) {
        vec3 A = seeded_point(rng, 100), B = seeded_point(rng, 100), C = seeded_point(rng, 100);
        real beta = (real)seeded_between(rng, -0.2, 1), gamma = (real)seeded_between(rng, -0.2, 1 - beta);
        vec3 got = interpolate_vec3(A, B, C, beta, gamma);
        suite_answer_vec3(describe("interpolate_vec3((%.9g, %.9g, %.9g), (%.9g, %.9g, %.9g), (%.9g, %.9g, %.9g), "
                                   "beta %.9g, gamma %.9g)",
                                   A.x, A.y, A.z, B.x, B.y, B.z, C.x, C.y, C.z, beta, gamma),
                          got, 64 * REAL_EPSILON * 100);
        mesh_uv a = {(real)suite_uniform(rng), (real)suite_uniform(rng)};
        mesh_uv b = {(real)suite_uniform(rng), (real)suite_uniform(rng)};
        mesh_uv c = {(real)suite_uniform(rng), (real)suite_uniform(rng)};
        mesh_uv uv = interpolate_uv(a, b, c, beta, gamma);
        const char *in = describe("interpolate_uv((%.9g, %.9g), (%.9g, %.9g), (%.9g, %.9g), beta %.9g, gamma %.9g)",
                                  a.u, a.v, b.u, b.v, c.u, c.v, beta, gamma);
        suite_answer(describe("%s: u", in), uv.u, 64 * REAL_EPSILON);
        suite_answer(describe("%s: v", in), uv.v, 64 * REAL_EPSILON);
    }
}

/* Texel indices of one kind: each test of texel_index checks its own kind's contract. */
static void answer_texel_indices(unsigned long *rng, texture_kind kind)
{
    for (int k = 0; k < 8; k++) {
        int n = 1 + (int)seeded_between(rng, 0, 300);
        long long i = (long long)seeded_between(rng, -3000, 3000);
        suite_answer(describe("texel_index(%s, %lld, %d)", kind == TEXTURE_CLAMP ? "clamp" : "repeat", i, n),
                     texel_index(kind, i, n), 0);
    }
}

static void seeded_texel_repeat(unsigned long *rng) { answer_texel_indices(rng, TEXTURE_REPEAT); }
static void seeded_texel_clamp(unsigned long *rng) { answer_texel_indices(rng, TEXTURE_CLAMP); }

/* A texture of random texels, w x h from 1 to 40 each (free tex->image.rgb). */
static scene_texture random_texture(unsigned long *rng, texture_kind kind)
{
    scene_texture tex = {.kind = kind};
    tex.image.width = 1 + (int)seeded_between(rng, 0, 40);
    tex.image.height = 1 + (int)seeded_between(rng, 0, 40);
    size_t n = (size_t)tex.image.width * (size_t)tex.image.height * 3;
    tex.image.rgb = malloc(n);
    if (!tex.image.rgb)
        fail_msg("out of memory");
    for (size_t k = 0; k < n; k++)
        tex.image.rgb[k] = (unsigned char)seeded_between(rng, 0, 256);
    return tex;
}

/* Lookups at (u, v) beyond the image on every side (negative: u and 1 - v
 * from -1.5, where indices are negative), or only right of and below it
 * (indices from 0: the side test_nearest and test_bilinear check, so that a
 * wrap wrong for negative indices costs only the tests of that side). */
static void answer_lookups(unsigned long *rng, texture_filter filter, int negative)
{
    for (int t = 0; t < 4; t++) {
        scene_texture tex = random_texture(rng, t % 2 ? TEXTURE_CLAMP : TEXTURE_REPEAT);
        double side = tex.image.width > tex.image.height ? tex.image.width : tex.image.height;
        for (int k = 0; k < 6; k++) {
            double low = negative ? -1.5 : 0; /* of u and of 1 - v */
            mesh_uv uv = {(real)seeded_between(rng, low, 2.5), (real)(1 - seeded_between(rng, low, 2.5))};
            color c = filter == TEXTURE_NEAREST ? texture_nearest(&tex, uv) : texture_bilinear(&tex, uv);
            suite_answer_rgb(describe("texture_%s(texture %d of %d x %d texels, %s, uv (%.9g, %.9g))",
                                      filter == TEXTURE_NEAREST ? "nearest" : "bilinear", t + 1, tex.image.width,
                                      tex.image.height, tex.kind == TEXTURE_CLAMP ? "clamp" : "repeat", uv.u, uv.v),
                             c, (filter == TEXTURE_NEAREST ? 4 : 64 * side) * REAL_EPSILON);
        }
        free(tex.image.rgb);
    }
}

static void seeded_nearest(unsigned long *rng) { answer_lookups(rng, TEXTURE_NEAREST, 0); }
static void seeded_nearest_quirk(unsigned long *rng) { answer_lookups(rng, TEXTURE_NEAREST, 1); }
static void seeded_bilinear(unsigned long *rng) { answer_lookups(rng, TEXTURE_BILINEAR, 0); }
static void seeded_bilinear_random(unsigned long *rng) { answer_lookups(rng, TEXTURE_BILINEAR, 1); }

SEEDED_CHECKS(SEEDED(test_interpolate_vertices_edges, seeded_interpolate),
              SEEDED(test_interpolate_random, seeded_interpolate), SEEDED(test_interpolate_uv, seeded_interpolate),
              SEEDED(test_texel_index_repeat, seeded_texel_repeat), SEEDED(test_texel_index_clamp, seeded_texel_clamp),
              SEEDED(test_nearest, seeded_nearest), SEEDED(test_nearest_quirk, seeded_nearest_quirk),
              SEEDED(test_bilinear, seeded_bilinear), SEEDED(test_bilinear_random, seeded_bilinear_random),
              SEEDED(test_vertex_normal, seeded_interpolate), SEEDED(test_smooth_shading, seeded_interpolate),
              SEEDED(test_textured_sphere, seeded_nearest))
