/* Chapter 01: the pixel-to-image mapping, the camera basis and the eye rays.
 *
 * Each exercise is tested on its own: the ray tests build the camera's basis
 * by hand, so a wrong camera_basis costs the basis tests only.  A failure
 * names the input, the expected value, the value got and the likely mistake
 * (assert_vec3_why, tests/suite.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "suite.h"

#define EPS ((double)REAL_EPSILON)

static scene_camera perspective(vec3 view_point, vec3 view_dir, vec3 view_up, real d, real width, real height)
{
    return (scene_camera){CAMERA_PERSPECTIVE, view_point, view_dir, view_up, d, width, height, 1};
}

/* The lecture's camera ("Specifying views"). */
static scene_camera lecture_camera(void)
{
    return perspective(vec3_make(10, (real)4.2, 6), vec3_make(-5, (real)-2.1, -3), vec3_make(0, 1, 0), 6, 4,
                       (real)2.25);
}

/* Looking down -z with y up: the basis is exactly x, y, z. */
static scene_camera axis_camera(camera_kind kind)
{
    scene_camera c = perspective(vec3_make(1, 2, 3), vec3_make(0, 0, -1), vec3_make(0, 1, 0), 2, 4, (real)2.25);
    c.kind = kind;
    return c;
}

static camera make(scene_camera desc)
{
    camera cam;
    const char *problem = camera_init(&cam, &desc);
    if (problem)
        fail_msg("camera_init: %s", problem);
    return cam;
}

#define N(a) (sizeof(a) / sizeof((a)[0]))

/* ---- the pixel-to-image mapping ------------------------------------------- */

/* u = (i + du)/n_x, v = (j + dv)/n_y: (i + du) is exact for these numbers
 * and the division rounds once, to within eps/2 relative.  Equivalent forms
 * (i/n_x + du/n_x, or a multiplication by 1/n_x) round two or three times:
 * 4 eps relative admits them all. */
static void expect_pixel(int i, int j, int nx, int ny, real du, real dv)
{
    real u = -1, v = -1;
    pixel_to_image(i, j, nx, ny, du, dv, &u, &v);
    double eu = (i + (double)du) / nx, ev = (j + (double)dv) / ny;
    const suspect su[] = {
        {(double)i / nx, "the sample offset is missing: pixel i is the square [i, i+1], its centre is at i + 0.5"},
        {(j + (double)dv) / ny, "u and v swapped: u goes with the column i and n_x, v with the row j and n_y"},
        {(i + (double)du) / (nx - 1), "divided by n_x - 1: the image is n_x pixels wide, u = (i + du) / n_x"},
        {1 - eu, "u flipped: i = 0 is the left column, at u near 0"},
        {(i + 0.5) / nx, "du ignored: the loop passes the sample's place inside the pixel, use it, not 0.5"},
        {(i + (double)dv) / nx, "du and dv swapped: du goes with i"},
        {(double)du / nx, "integer division: i / n_x is 0 in C for ints; convert i to real before dividing"},
        {(i + (double)du) / ny, "u divided by n_y: u goes with n_x, the image's width in pixels"},
        {(nx - 1 - i + (double)du) / nx, "u flipped: i = 0 is the left column, at u near 0"},
    };
    const suspect sv[] = {
        {(double)j / ny, "the sample offset is missing: pixel j is the square [j, j+1], its centre is at j + 0.5"},
        {eu, "u and v swapped: v goes with the row j and n_y"},
        {(j + (double)dv) / (ny - 1), "divided by n_y - 1: the image is n_y pixels high, v = (j + dv) / n_y"},
        {1 - ev, "v flipped: j = 0 is the bottom row, at v near 0 (the PNG writer flips the rows, not you)"},
        {(j + 0.5) / ny, "dv ignored: the loop passes the sample's place inside the pixel, use it, not 0.5"},
        {(j + (double)du) / ny, "du and dv swapped: dv goes with j"},
        {(double)dv / ny, "integer division: j / n_y is 0 in C for ints; convert j to real before dividing"},
        {(j + (double)dv) / nx, "v divided by n_x: v goes with n_y, the image's height in pixels"},
        {(ny - 1 - j + (double)dv) / ny,
         "v flipped: j = 0 is the bottom row, at v near 0 (the PNG writer flips the rows, not you)"},
    };
    assert_close_why(eu, u, 4 * EPS * eu, describe("pixel_to_image(i=%d, j=%d, nx=%d, ny=%d, du=%g, dv=%g): u", i, j, nx, ny,
                                          (double)du, (double)dv),
                     "u = (i + du) / n_x", su, N(su));
    assert_close_why(ev, v, 4 * EPS * ev, describe("pixel_to_image(i=%d, j=%d, nx=%d, ny=%d, du=%g, dv=%g): v", i, j, nx, ny,
                                          (double)du, (double)dv),
                     "v = (j + dv) / n_y", sv, N(sv));
}

/* Every pixel centre of a 7 x 3 image (not square, so that u and v cannot
 * be swapped unseen), and the corner pixels of a 40000 x 30000 image, whose
 * last centres lie just below 1. */
static void test_pixel_centres(void **state)
{
    (void)state;
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 7; i++)
            expect_pixel(i, j, 7, 3, (real)0.5, (real)0.5);
    const int big[][2] = {{0, 0}, {39999, 0}, {0, 29999}, {39999, 29999}, {12345, 6789}};
    for (size_t k = 0; k < N(big); k++)
        expect_pixel(big[k][0], big[k][1], 40000, 30000, (real)0.5, (real)0.5);
}

/* With several samples per pixel the loop passes each sample's place: the
 * offsets are used as given, du with i and dv with j. */
static void test_pixel_sample_offsets(void **state)
{
    (void)state;
    expect_pixel(2, 1, 5, 4, (real)0.125, (real)0.8125);
    expect_pixel(4, 3, 5, 4, (real)0.9375, (real)0.0625);
    expect_pixel(0, 0, 3, 9, 0, 0);
}

/* ---- the basis ------------------------------------------------------------ */

/* The lecture's camera: viewDir (-5, -2.1, -3), viewUp (0, 1, 0), which are
 * not perpendicular.  The expected basis is computed here in the same
 * precision: each vector is within a few roundings of it (8 eps). */
static void test_basis_lecture_camera(void **state)
{
    (void)state;
    const vec3 dir = {-5, (real)-2.1, -3}, up = {0, 1, 0};
    vec3 u, v, w;
    camera_basis(dir, up, &u, &v, &w);
    const vec3 ew = vec3_neg(vec3_normalize(dir));
    const vec3 eu = vec3_normalize(vec3_cross(dir, up));
    const vec3 ev = vec3_cross(ew, eu);
    const char *in = "camera_basis(viewDir = (-5, -2.1, -3), viewUp = (0, 1, 0))";
    const suspect_vec3 sw[] = {
        {vec3_neg(ew), "wrong sign of w: the camera looks along -w, so w = -viewDir / |viewDir|"},
        {vec3_neg(dir), "w not normalized: w = -viewDir / |viewDir|"},
        {vec3_normalize(vec3_cross(up, dir)), "w computed as u"},
    };
    assert_vec3_why(ew, w, 8 * EPS, describe("%s: w", in), "w = -viewDir / |viewDir|", sw, N(sw));
    const suspect_vec3 su[] = {
        {vec3_neg(eu), "u points left: u = viewDir x viewUp (the order of the cross product matters)"},
        {vec3_cross(dir, up), "u not normalized: |viewDir x viewUp| is 1 only for perpendicular unit vectors"},
        {vec3_cross(vec3_normalize(dir), up),
         "u not normalized: viewDir and viewUp are not perpendicular, so their cross product is shorter than 1"},
    };
    assert_vec3_why(eu, u, 8 * EPS, describe("%s: u", in), "u = (viewDir x viewUp) / |viewDir x viewUp|", su, N(su));
    const suspect_vec3 sv[] = {
        {vec3_neg(ev), "v points down: v = w x u (u x w is its negative)"},
        {up, "v taken as viewUp: viewUp only says which way is up; v = w x u is perpendicular to w"},
        {vec3_cross(vec3_neg(ew), eu), "v computed with the wrong sign of w"},
    };
    assert_vec3_why(ev, v, 8 * EPS, describe("%s: v", in), "v = w x u", sv, N(sv));
}

/* ---- the rays, with a basis built here ------------------------------------ */

/* A camera in general position far from the origin, with its basis set by
 * hand (an orthonormal frame around (2, 3, -6)/7), so that the ray tests do
 * not depend on camera_basis.  Not square, and d not 1, so that swapping
 * u and v or forgetting projDistance shows. */
static camera hand_camera(camera_kind kind, vec3 e)
{
    camera cam;
    cam.kind = kind;
    cam.e = e;
    cam.w = vec3_normalize(vec3_make(-2, -3, 6)); /* looking along (2, 3, -6) */
    cam.u = vec3_normalize(vec3_make(3, -2, 0));
    cam.v = vec3_cross(cam.w, cam.u);
    cam.d = (real)1.7;
    cam.width = 4;
    cam.height = (real)2.25;
    return cam;
}

static const real positions[][2] = {{0.3, 0.8}, {0, 0}, {1, 1}, {0.9, 0.15}, {0.5, 0.5}, {0.0625, 0.6}};

static vec3 combine(real a, vec3 x, real b, vec3 y, real c, vec3 z)
{
    return vec3_add(vec3_add(vec3_scale(x, a), vec3_scale(y, b)), vec3_scale(z, c));
}

/* Mistakes in the point of the image rectangle, (u_s, v_s), which both projections share. */
#define NOT_CENTRED "the rectangle not centred on the view direction: u_s = (u - 1/2) viewWidth, v_s = (v - 1/2) viewHeight"
#define V_S_BY_WIDTH "v_s scaled by viewWidth: v_s = (v - 1/2) viewHeight"
#define U_S_BY_HEIGHT "u_s scaled by viewHeight: u_s = (u - 1/2) viewWidth"
#define W_H_SWAPPED "viewWidth and viewHeight swapped: u_s = (u - 1/2) viewWidth, v_s = (v - 1/2) viewHeight"

/* d = -d w + u_s u + v_s v, each component a sum of three products of size
 * at most d + width/2 + height/2 < 5: 8 eps of 5 bounds the rounding. */
static void expect_perspective(const camera *cam, real u, real v)
{
    ray r = camera_ray(cam, u, v);
    real us = (u - (real)0.5) * cam->width, vs = (v - (real)0.5) * cam->height;
    const vec3 ed = combine(-cam->d, cam->w, us, cam->u, vs, cam->v);
    const char *in = describe("camera_ray(perspective, e = (%g, %g, %g), d = %g, %g x %g; u = %g, v = %g)", cam->e.x,
                         cam->e.y, cam->e.z, (double)cam->d, (double)cam->width, (double)cam->height, (double)u,
                         (double)v);
    char where[600];
    snprintf(where, sizeof where, "%s: p", in);
    const suspect_vec3 sp[] = {
        {vec3_add(cam->e, combine(0, cam->w, us, cam->u, vs, cam->v)),
         "the orthographic origin: perspective rays all start at the eye, p = e"},
        {vec3_make(0, 0, 0), "p not set: p = e"},
    };
    assert_vec3_why(cam->e, r.p, 0, where, "p = e, the eye", sp, N(sp));
    snprintf(where, sizeof where, "%s: d", in);
    const suspect_vec3 sd[] = {
        {combine(cam->d, cam->w, us, cam->u, vs, cam->v),
         "wrong sign of w: the camera looks along -w, d = -d w + u_s u + v_s v"},
        {combine(-1, cam->w, us, cam->u, vs, cam->v), "projDistance missing: the image plane is at distance d, -d w"},
        {vec3_normalize(ed), "d normalized: keep d = -d w + u_s u + v_s v as it is, so that t = 1 is the image plane"},
        {combine(-cam->d, cam->w, -us, cam->u, -vs, cam->v), "the offset subtracted: d = -d w + u_s u + v_s v"},
        {combine(-cam->d, cam->w, vs, cam->u, us, cam->v), "u_s and v_s swapped: u_s goes with u, v_s with v"},
        {combine(-cam->d, cam->w, us, cam->u, -vs, cam->v), "v flipped: + v_s v"},
        {vec3_add(cam->e, ed), "the eye added to d: d is a direction, the point e + d is on the image plane"},
        {vec3_neg(cam->w), "the orthographic direction: perspective rays go through their point of the image"},
        {combine(-cam->d, cam->w, u * cam->width, cam->u, v * cam->height, cam->v), NOT_CENTRED},
        {combine(-cam->d, cam->w, u * cam->width - (real)0.5, cam->u, v * cam->height - (real)0.5, cam->v),
         "u_s = u viewWidth - 1/2: take 1/2 from u before scaling, u_s = (u - 1/2) viewWidth"},
        {combine(-cam->d, cam->w, us, cam->u, (v - (real)0.5) * cam->width, cam->v), V_S_BY_WIDTH},
        {combine(-cam->d, cam->w, (u - (real)0.5) * cam->height, cam->u, vs, cam->v), U_S_BY_HEIGHT},
        {combine(-cam->d, cam->w, (u - (real)0.5) * cam->height, cam->u, (v - (real)0.5) * cam->width, cam->v),
         W_H_SWAPPED},
    };
    assert_vec3_why(ed, r.d, 8 * EPS * 5, where, "d = -d w + u_s u + v_s v (d: projDistance)", sd, N(sd));
}

static void test_perspective_rays(void **state)
{
    (void)state;
    const vec3 eyes[] = {{1, 2, 3}, {(real)-3.7e4, (real)1.25e5, (real)6.1e3}, {(real)1e15, (real)-2e15, 0}};
    for (size_t k = 0; k < N(eyes); k++) {
        camera cam = hand_camera(CAMERA_PERSPECTIVE, eyes[k]);
        for (size_t m = 0; m < N(positions); m++)
            expect_perspective(&cam, positions[m][0], positions[m][1]);
    }
}

/* p = e + u_s u + v_s v: the offset (size < 3) is rounded in three products
 * and a sum, then added to e, which rounds once more relative to |e|:
 * 8 eps (|e| + 3).  d = -w exactly. */
static void expect_orthographic(const camera *cam, real u, real v)
{
    ray r = camera_ray(cam, u, v);
    real us = (u - (real)0.5) * cam->width, vs = (v - (real)0.5) * cam->height;
    const vec3 offset = combine(0, cam->w, us, cam->u, vs, cam->v);
    const vec3 ep = vec3_add(cam->e, offset);
    const char *in = describe("camera_ray(orthographic, e = (%g, %g, %g), %g x %g; u = %g, v = %g)", cam->e.x, cam->e.y,
                         cam->e.z, (double)cam->width, (double)cam->height, (double)u, (double)v);
    char where[600];
    snprintf(where, sizeof where, "%s: p", in);
    const suspect_vec3 sp[] = {
        {cam->e, "every ray starts at the eye: orthographic rays start at their point of the image, e + u_s u + v_s v"},
        {vec3_sub(cam->e, offset), "the offset subtracted: p = e + u_s u + v_s v"},
        {vec3_add(ep, vec3_scale(cam->w, -cam->d)),
         "the origin moved to the image plane at distance d: the orthographic rectangle is centred on the eye"},
        {offset, "e missing: p = e + u_s u + v_s v"},
        {vec3_add(cam->e, combine(0, cam->w, vs, cam->u, us, cam->v)), "u_s and v_s swapped"},
        {vec3_add(cam->e, combine(0, cam->w, us, cam->u, -vs, cam->v)), "v flipped: + v_s v"},
        {vec3_add(cam->e, combine(0, cam->w, u * cam->width, cam->u, v * cam->height, cam->v)), NOT_CENTRED},
        {vec3_add(cam->e, combine(0, cam->w, us, cam->u, (v - (real)0.5) * cam->width, cam->v)), V_S_BY_WIDTH},
        {vec3_add(cam->e, combine(0, cam->w, (u - (real)0.5) * cam->height, cam->u, vs, cam->v)), U_S_BY_HEIGHT},
        {vec3_add(cam->e, combine(0, cam->w, (u - (real)0.5) * cam->height, cam->u, (v - (real)0.5) * cam->width,
                                  cam->v)),
         W_H_SWAPPED},
    };
    double size = vec3_max_abs(cam->e) + 3;
    assert_vec3_why(ep, r.p, 8 * EPS * size, where, "p = e + u_s u + v_s v", sp, N(sp));
    snprintf(where, sizeof where, "%s: d", in);
    const suspect_vec3 sd[] = {
        {cam->w, "wrong sign of w: the camera looks along -w, d = -w"},
        {vec3_scale(cam->w, -cam->d), "d scaled by projDistance: orthographic rays have d = -w"},
        {combine(-cam->d, cam->w, us, cam->u, vs, cam->v),
         "the perspective direction: orthographic rays are parallel, d = -w for all"},
        {vec3_make(0, 0, 0), "d not set: d = -w"},
    };
    /* -w itself is exact; normalize(-w), which w (unit) allows, rounds the
     * squares, their sum, the root and the division: a few eps at most */
    assert_vec3_why(vec3_neg(cam->w), r.d, 4 * EPS, where, "d = -w, the same for every ray", sd, N(sd));
}

static void test_orthographic_rays(void **state)
{
    (void)state;
    const vec3 eyes[] = {{1, 2, 3}, {(real)-3.7e4, (real)1.25e5, (real)6.1e3}, {(real)0.001, (real)-0.002, 0}};
    for (size_t k = 0; k < N(eyes); k++) {
        camera cam = hand_camera(CAMERA_ORTHOGRAPHIC, eyes[k]);
        for (size_t m = 0; m < N(positions); m++)
            expect_orthographic(&cam, positions[m][0], positions[m][1]);
    }
}

/* Each basis vector is a few roundings from exact: normalizing costs about
 * 3 eps, the cross products 2 eps per component, so 8 eps bounds each
 * dot product of the basis with itself or another basis vector. */
static void expect_orthonormal_right_handed(camera cam, vec3 dir, vec3 up)
{
    char in[200];
    snprintf(in, sizeof in, "camera_basis(viewDir = (%g, %g, %g), viewUp = (%g, %g, %g))", (double)dir.x,
             (double)dir.y, (double)dir.z, (double)up.x, (double)up.y, (double)up.z);
    const char *unit = "a basis vector is not of unit length: normalize u and w with unit() (v = w x u is then unit)";
    assert_close_why(1, vec3_dot(cam.u, cam.u), 8 * EPS, describe("%s: u.u", in), unit, NULL, 0);
    assert_close_why(1, vec3_dot(cam.v, cam.v), 8 * EPS, describe("%s: v.v", in), unit, NULL, 0);
    assert_close_why(1, vec3_dot(cam.w, cam.w), 8 * EPS, describe("%s: w.w", in), unit, NULL, 0);
    const char *perp = "not perpendicular: u = viewDir x viewUp and v = w x u, not viewUp itself";
    assert_close_why(0, vec3_dot(cam.u, cam.v), 8 * EPS, describe("%s: u.v", in), perp, NULL, 0);
    assert_close_why(0, vec3_dot(cam.v, cam.w), 8 * EPS, describe("%s: v.w", in), perp, NULL, 0);
    assert_close_why(0, vec3_dot(cam.w, cam.u), 8 * EPS, describe("%s: w.u", in), perp, NULL, 0);
    const suspect_vec3 left[] = {{vec3_neg(cam.w), "left-handed: u x v = -w; check the order of both cross products"}};
    assert_vec3_why(cam.w, vec3_cross(cam.u, cam.v), 8 * EPS, describe("%s: u x v", in), "u x v must be w (right-handed)",
                    left, 1);
}

static void test_basis_orthonormal_right_handed(void **state)
{
    (void)state;
    static const vec3 dirs[] = {{-5, (real)-2.1, -3}, {0, 0, -1}, {1, 0, 0}, {(real)0.3, -10, (real)0.2},
                                {(real)1e30, (real)-1e30, (real)2e30}, {(real)1e-30, (real)3e-30, (real)-2e-30}};
    static const vec3 ups[] = {{0, 1, 0}, {(real)0.2, 5, (real)-0.1}, {0, 0, 1}, {(real)1e-20, (real)3e-20, 0}};
    for (size_t i = 0; i < sizeof dirs / sizeof dirs[0]; i++) {
        for (size_t k = 0; k < sizeof ups / sizeof ups[0]; k++) {
            scene_camera desc = perspective(vec3_make(0, 0, 0), dirs[i], ups[k], 1, 1, 1);
            camera cam;
            if (camera_init(&cam, &desc) != NULL)
                continue; /* viewUp parallel to viewDir: tested below */
            expect_orthonormal_right_handed(cam, dirs[i], ups[k]);
            /* -w points along viewDir; v leans towards viewUp */
            const char *in = describe("camera_basis(viewDir = (%g, %g, %g), viewUp = (%g, %g, %g)): -w . viewDir/|viewDir|",
                                 (double)dirs[i].x, (double)dirs[i].y, (double)dirs[i].z, (double)ups[k].x,
                                 (double)ups[k].y, (double)ups[k].z);
            const suspect back[] = {{-1, "wrong sign of w: w = -viewDir / |viewDir|"}};
            assert_close_why(1, vec3_dot(vec3_neg(cam.w), vec3_normalize(vec3_scale(dirs[i], 1 / vec3_max_abs(dirs[i])))),
                             8 * EPS, in, "w = -viewDir / |viewDir| (normalize with unit(): |viewDir| may overflow)",
                             back, 1);
            const suspect down[] = {{-1, "v points down: v = w x u, and u = viewDir x viewUp (in that order)"}};
            real lean = vec3_dot(cam.v, ups[k]) > 0 ? 1 : -1;
            assert_close_why(1, lean, 0, describe("the sign of v . viewUp for viewDir = (%g, %g, %g), viewUp = (%g, %g, %g)",
                                             (double)dirs[i].x, (double)dirs[i].y, (double)dirs[i].z, (double)ups[k].x,
                                             (double)ups[k].y, (double)ups[k].z),
                             "v must lean towards viewUp", down, 1);
        }
    }
}

static void test_basis_of_axis_camera_is_exact(void **state)
{
    (void)state;
    camera cam = make(axis_camera(CAMERA_PERSPECTIVE));
    const char *in = "camera_basis(viewDir = (0, 0, -1), viewUp = (0, 1, 0))";
    const suspect_vec3 su[] = {{vec3_make(-1, 0, 0), "u points left: u = viewDir x viewUp, in that order"}};
    const suspect_vec3 sv[] = {{vec3_make(0, -1, 0), "v points down: v = w x u, in that order"}};
    const suspect_vec3 sw[] = {{vec3_make(0, 0, -1), "wrong sign of w: w = -viewDir / |viewDir|"}};
    assert_vec3_why(vec3_make(1, 0, 0), cam.u, 0, describe("%s: u", in), "u = (viewDir x viewUp) / |...|", su, 1);
    assert_vec3_why(vec3_make(0, 1, 0), cam.v, 0, describe("%s: v", in), "v = w x u", sv, 1);
    assert_vec3_why(vec3_make(0, 0, 1), cam.w, 0, describe("%s: w", in), "w = -viewDir / |viewDir|", sw, 1);
}

/* viewDir and viewUp of any size give the same basis (the exercise's unit()).
 * Here both are scaled by 2^k or 2^-k with k three quarters of the exponent
 * range (2^768 in double, 2^96 in float), so that a product of two of their
 * components overflows, or underflows to 0: a cross product or a dot product
 * of the raw vectors is infinite or zero, and its direction NaN.  unit()
 * divides by the largest component first, so the basis is that of
 * viewDir (-2, -1, -2), viewUp (0, 1, 0):
 *     w = (2, 1, 2) / 3,  u = (1, 0, -1) / sqrt 2,  v = w x u = (-1, 4, -1) / (3 sqrt 2),
 * each within a few roundings, 8 eps as in test_basis_lecture_camera. */
static void test_basis_of_huge_and_tiny_vectors(void **state)
{
    (void)state;
    const int k = (REAL_EPSILON < 1e-10 ? 1024 : 128) * 3 / 4;
    const real huge = (real)ldexp(1, k), tiny = (real)ldexp(1, -k);
    const real scales[][2] = {{huge, huge}, {tiny, tiny}, {huge, tiny}, {tiny, huge}};
    const double r2 = sqrt(2.0);
    const vec3 ew = vec3_make((real)(2.0 / 3), (real)(1.0 / 3), (real)(2.0 / 3));
    const vec3 eu = vec3_make((real)(1 / r2), 0, (real)(-1 / r2));
    const vec3 ev = vec3_make((real)(-1 / (3 * r2)), (real)(4 / (3 * r2)), (real)(-1 / (3 * r2)));
    const char *raw = "a product of two components overflowed or underflowed: normalize with unit(), which divides by "
                      "the largest component first, and take u from unit(viewDir) x unit(viewUp), not from the raw "
                      "vectors";
    const suspect_vec3 overflow[] = {{vec3_make((real)NAN, (real)NAN, (real)NAN), raw}};
    for (size_t m = 0; m < N(scales); m++) {
        const vec3 dir = vec3_scale(vec3_make(-2, -1, -2), scales[m][0]), up = vec3_make(0, scales[m][1], 0);
        vec3 u, v, w;
        camera_basis(dir, up, &u, &v, &w);
        const char *in = describe("camera_basis(viewDir = 2^%d (-2, -1, -2), viewUp = 2^%d (0, 1, 0))",
                                  scales[m][0] > 1 ? k : -k, scales[m][1] > 1 ? k : -k);
        assert_vec3_why(ew, w, 8 * EPS, describe("%s: w", in), raw, overflow, N(overflow));
        assert_vec3_why(eu, u, 8 * EPS, describe("%s: u", in), raw, overflow, N(overflow));
        assert_vec3_why(ev, v, 8 * EPS, describe("%s: v", in), raw, overflow, N(overflow));
    }
}

static void test_centre_ray_along_view_dir(void **state)
{
    (void)state;
    scene_camera desc = lecture_camera();
    camera cam = make(desc);
    ray r = camera_ray(&cam, (real)0.5, (real)0.5);
    const char *in = "the centre ray (u = v = 0.5) of the lecture camera (projDistance 6)";
    assert_vec3_why(desc.view_point, r.p, 0, describe("%s: p", in), "p = e, the eye", NULL, 0);
    /* d = -d w: projDistance times the unit view direction */
    vec3 expected = vec3_scale(vec3_normalize(desc.view_dir), 6);
    const suspect_vec3 sd[] = {{vec3_normalize(desc.view_dir), "d normalized, or projDistance missing: d = -d w"},
                               {vec3_neg(expected), "wrong sign of w: the camera looks along -w"}};
    assert_vec3_why(expected, r.d, 6 * 8 * EPS, describe("%s: d", in), "d = -d w + u_s u + v_s v", sd, N(sd));
}

static void test_four_corner_rays_exactly(void **state)
{
    (void)state;
    camera cam = make(axis_camera(CAMERA_PERSPECTIVE));
    /* d = -d w + us u + vs v with us = (u - 1/2) 4, vs = (v - 1/2) 2.25, d = 2:
     * every number is a short binary fraction, so the rays are exact. */
    const struct {
        real u, v;
        vec3 d;
    } corners[] = {
        {0, 0, {-2, (real)-1.125, -2}},
        {1, 0, {2, (real)-1.125, -2}},
        {0, 1, {-2, (real)1.125, -2}},
        {1, 1, {2, (real)1.125, -2}},
    };
    for (int k = 0; k < 4; k++) {
        ray r = camera_ray(&cam, corners[k].u, corners[k].v);
        const char *in = describe("camera_ray(camera at (1, 2, 3) looking down -z, d = 2, 4 x 2.25; u = %g, v = %g)",
                             (double)corners[k].u, (double)corners[k].v);
        assert_vec3_why(vec3_make(1, 2, 3), r.p, 0, in, "p = e, the eye", NULL, 0);
        const suspect_vec3 sd[] = {
            {vec3_make(corners[k].d.x, -corners[k].d.y, -2), "v flipped: + v_s v"},
            {vec3_make(corners[k].d.x, corners[k].d.y, 2), "wrong sign of w: -d w"},
            {vec3_make(corners[k].d.x, corners[k].d.y, -1), "projDistance missing: -d w"},
        };
        assert_vec3_why(corners[k].d, r.d, 0, in, "d = -d w + u_s u + v_s v, exact for these numbers", sd, N(sd));
    }
}

static void test_projection_distance_scales_the_view(void **state)
{
    (void)state;
    /* The lecture's two cameras: projDistance 6 and 3.  The corner ray of the
     * nearer image plane is twice as steep off the view direction. */
    scene_camera far = lecture_camera(), near = lecture_camera();
    near.proj_distance = 3;
    camera a = make(far), b = make(near);
    ray ra = camera_ray(&a, 1, 1), rb = camera_ray(&b, 1, 1);
    real off_a = vec3_dot(ra.d, a.u) / -vec3_dot(ra.d, a.w);
    real off_b = vec3_dot(rb.d, b.u) / -vec3_dot(rb.d, b.w);
    const suspect s[] = {{2.0 / 4 / 1, "projDistance missing: d = -d w + ..."}};
    assert_close_why(2.0 / 6, off_a, 16 * EPS, "the lecture camera, projDistance 6: corner ray's slope (d.u)/(-d.w)",
                     "d = -d w + u_s u + v_s v", s, 1);
    assert_close_why(2.0 / 3, off_b, 16 * EPS, "the lecture camera, projDistance 3: corner ray's slope (d.u)/(-d.w)",
                     "d = -d w + u_s u + v_s v", s, 1);
}

static void test_orthographic_rays_parallel_from_image_plane(void **state)
{
    (void)state;
    scene_camera desc = lecture_camera();
    desc.kind = CAMERA_ORTHOGRAPHIC;
    camera cam = make(desc);
    vec3 dir = vec3_normalize(desc.view_dir);
    for (int k = 0; k <= 4; k++) {
        real u = (real)k / 4, v = (real)(4 - k) / 4;
        ray r = camera_ray(&cam, u, v);
        const char *in = describe("camera_ray(orthographic lecture camera; u = %g, v = %g)", (double)u, (double)v);
        assert_vec3_why(dir, r.d, 8 * EPS, describe("%s: d", in), "d = -w for every ray (unit: w is)", NULL, 0);
        /* the origin lies on the plane through viewPoint perpendicular to w,
         * at (u - 1/2) viewWidth along u and (v - 1/2) viewHeight along v;
         * offsets up to 2 units from a viewPoint of size 12: 16 eps of 12 */
        vec3 offset = vec3_sub(r.p, desc.view_point);
        const char *hint = "p = e + u_s u + v_s v: the rectangle is centred on the eye, in the plane of u and v";
        assert_close_why(0, vec3_dot(offset, cam.w), 16 * EPS * 12, describe("%s: (p - e).w", in), hint, NULL, 0);
        assert_close_why((u - 0.5) * 4, vec3_dot(offset, cam.u), 16 * EPS * 12, describe("%s: (p - e).u", in), hint, NULL, 0);
        assert_close_why((v - 0.5) * 2.25, vec3_dot(offset, cam.v), 16 * EPS * 12, describe("%s: (p - e).v", in), hint,
                         NULL, 0);
    }
    camera axis = make(axis_camera(CAMERA_ORTHOGRAPHIC));
    ray corner = camera_ray(&axis, 0, 1);
    const char *in = "camera_ray(orthographic camera at (1, 2, 3) looking down -z, 4 x 2.25; u = 0, v = 1)";
    const suspect_vec3 sp[] = {{vec3_make(1, 2, 3), "every ray starts at the eye: p = e + u_s u + v_s v"}};
    assert_vec3_why(vec3_make(-1, (real)3.125, 3), corner.p, 0, describe("%s: p", in), "p = e + u_s u + v_s v", sp, 1);
    assert_vec3_why(vec3_make(0, 0, -1), corner.d, 0, describe("%s: d", in), "d = -w", NULL, 0);
}

static void test_pixel_centres_of_non_square_image(void **state)
{
    (void)state;
    /* 320 x 180 pixels on a 4 x 2.25 rectangle: pixel (0, 0) is at
     * u = 0.5/320, v = 0.5/180, so its ray leaves the corner by half a pixel:
     * us = -2 + 4 * 0.5/320 = -1.99375, vs = -1.125 + 2.25 * 0.5/180 = -1.11875 */
    camera cam = make(axis_camera(CAMERA_PERSPECTIVE));
    ray r = camera_ray(&cam, (real)(0.5 / 320), (real)(0.5 / 180));
    const char *hint = "d = -d w + u_s u + v_s v";
    assert_vec3_why(vec3_make((real)-1.99375, (real)-1.11875, -2), r.d, 4 * EPS * 2,
                    "camera_ray(camera looking down -z, 4 x 2.25, d = 2; pixel (0, 0) of 320 x 180).d", hint, NULL, 0);
    /* The last pixel (319, 179) mirrors it */
    r = camera_ray(&cam, (real)(319.5 / 320), (real)(179.5 / 180));
    assert_vec3_why(vec3_make((real)1.99375, (real)1.11875, -2), r.d, 4 * EPS * 2,
                    "camera_ray(camera looking down -z, 4 x 2.25, d = 2; pixel (319, 179) of 320 x 180).d", hint, NULL,
                    0);
}

static void expect_rejected(scene_camera desc, const char *words)
{
    camera cam;
    const char *problem = camera_init(&cam, &desc);
    if (!problem || !strstr(problem, words))
        fail_msg("expected the camera to be rejected with '%s', got '%s'", words, problem ? problem : "(accepted)");
}

static void test_degenerate_cameras_rejected(void **state)
{
    (void)state;
    vec3 o = {0, 0, 0}, up = {0, 1, 0}, dir = {0, 0, -1};
    expect_rejected(perspective(o, vec3_make(0, 0, 0), up, 1, 1, 1), "viewDir is the zero vector");
    expect_rejected(perspective(o, dir, vec3_make(0, 0, 0), 1, 1, 1), "viewUp is the zero vector");
    expect_rejected(perspective(o, vec3_make(0, 2, 0), up, 1, 1, 1), "parallel");
    expect_rejected(perspective(o, vec3_make(0, -3, 0), up, 1, 1, 1), "parallel"); /* anti-parallel */
    /* nearly parallel, below sqrt(eps) of angle */
    expect_rejected(perspective(o, vec3_make((real)(EPS / 4), 1, 0), up, 1, 1, 1), "parallel");
    expect_rejected(perspective(o, dir, up, 0, 1, 1), "projDistance");
    expect_rejected(perspective(o, dir, up, -1, 1, 1), "projDistance");
    expect_rejected(perspective(o, dir, up, 1, 0, 1), "viewWidth");
    expect_rejected(perspective(o, dir, up, 1, 1, -2), "viewHeight");
    /* A steep but valid camera: 1e-3 radians between viewDir and viewUp */
    scene_camera steep = perspective(o, vec3_make((real)1e-3, 1, 0), up, 1, 1, 1);
    expect_orthonormal_right_handed(make(steep), steep.view_dir, steep.view_up);
    /* An orthographic camera needs no projDistance */
    scene_camera ortho = perspective(o, dir, up, 0, 1, 1);
    ortho.kind = CAMERA_ORTHOGRAPHIC;
    make(ortho);
}

static const graded_test tests[] = {
    GRADED(test_pixel_centres, 3),
    GRADED(test_pixel_sample_offsets, 1),
    GRADED(test_basis_lecture_camera, 2),
    GRADED(test_basis_orthonormal_right_handed, 2),
    GRADED(test_basis_of_axis_camera_is_exact, 1),
    GRADED(test_basis_of_huge_and_tiny_vectors, 1),
    GRADED(test_perspective_rays, 3),
    GRADED(test_orthographic_rays, 3),
    GRADED(test_centre_ray_along_view_dir, 1),
    GRADED(test_four_corner_rays_exactly, 1),
    GRADED(test_projection_distance_scales_the_view, 1),
    GRADED(test_orthographic_rays_parallel_from_image_plane, 1),
    GRADED(test_pixel_centres_of_non_square_image, 1),
    GRADED(test_degenerate_cameras_rejected, 1),
};
SUITE_MAIN("01_camera_rays", tests)
