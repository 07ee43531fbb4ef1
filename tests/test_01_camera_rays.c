/* Chapter 01: the camera basis and the eye rays. */
#include <string.h>

#include "01_camera_rays/camera.h"
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

/* Each basis vector is a few roundings from exact: normalizing costs about
 * 3 eps, the cross products 2 eps per component, so 8 eps bounds each
 * dot product of the basis with itself or another basis vector. */
static void expect_orthonormal_right_handed(camera cam)
{
    assert_close(1, vec3_dot(cam.u, cam.u), 8 * EPS);
    assert_close(1, vec3_dot(cam.v, cam.v), 8 * EPS);
    assert_close(1, vec3_dot(cam.w, cam.w), 8 * EPS);
    assert_close(0, vec3_dot(cam.u, cam.v), 8 * EPS);
    assert_close(0, vec3_dot(cam.v, cam.w), 8 * EPS);
    assert_close(0, vec3_dot(cam.w, cam.u), 8 * EPS);
    assert_vec3_close(cam.w, vec3_cross(cam.u, cam.v), 8 * EPS); /* u x v = w: right-handed */
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
            expect_orthonormal_right_handed(cam);
            /* -w points along viewDir; v leans towards viewUp */
            assert_close(1, vec3_dot(vec3_neg(cam.w), vec3_normalize(vec3_scale(dirs[i], 1 / vec3_max_abs(dirs[i])))),
                         8 * EPS);
            assert_true(vec3_dot(cam.v, ups[k]) > 0);
        }
    }
}

static void test_basis_of_axis_camera_is_exact(void **state)
{
    (void)state;
    camera cam = make(axis_camera(CAMERA_PERSPECTIVE));
    assert_vec3_close(vec3_make(1, 0, 0), cam.u, 0);
    assert_vec3_close(vec3_make(0, 1, 0), cam.v, 0);
    assert_vec3_close(vec3_make(0, 0, 1), cam.w, 0);
}

static void test_centre_ray_along_view_dir(void **state)
{
    (void)state;
    scene_camera desc = lecture_camera();
    camera cam = make(desc);
    ray r = camera_ray(&cam, (real)0.5, (real)0.5);
    assert_vec3_close(desc.view_point, r.p, 0);
    /* d = -d w: projDistance times the unit view direction */
    vec3 expected = vec3_scale(vec3_normalize(desc.view_dir), 6);
    assert_vec3_close(expected, r.d, 6 * 8 * EPS);
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
        assert_vec3_close(vec3_make(1, 2, 3), r.p, 0);
        assert_vec3_close(corners[k].d, r.d, 0);
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
    assert_close(2.0 / 6, off_a, 16 * EPS);
    assert_close(2.0 / 3, off_b, 16 * EPS);
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
        assert_vec3_close(dir, r.d, 8 * EPS); /* the same direction for every ray */
        /* the origin lies on the plane through viewPoint perpendicular to w,
         * at (u - 1/2) viewWidth along u and (v - 1/2) viewHeight along v;
         * offsets up to 2 units from a viewPoint of size 12: 16 eps of 12 */
        vec3 offset = vec3_sub(r.p, desc.view_point);
        assert_close(0, vec3_dot(offset, cam.w), 16 * EPS * 12);
        assert_close((u - 0.5) * 4, vec3_dot(offset, cam.u), 16 * EPS * 12);
        assert_close((v - 0.5) * 2.25, vec3_dot(offset, cam.v), 16 * EPS * 12);
    }
    camera axis = make(axis_camera(CAMERA_ORTHOGRAPHIC));
    ray corner = camera_ray(&axis, 0, 1);
    assert_vec3_close(vec3_make(-1, (real)3.125, 3), corner.p, 0);
    assert_vec3_close(vec3_make(0, 0, -1), corner.d, 0);
}

static void test_pixel_centres_of_non_square_image(void **state)
{
    (void)state;
    /* 320 x 180 pixels on a 4 x 2.25 rectangle: pixel (0, 0) is at
     * u = 0.5/320, v = 0.5/180, so its ray leaves the corner by half a pixel:
     * us = -2 + 4 * 0.5/320 = -1.99375, vs = -1.125 + 2.25 * 0.5/180 = -1.11875 */
    camera cam = make(axis_camera(CAMERA_PERSPECTIVE));
    ray r = camera_ray(&cam, (real)(0.5 / 320), (real)(0.5 / 180));
    assert_close(-1.99375, r.d.x, 4 * EPS * 2);
    assert_close(-1.11875, r.d.y, 4 * EPS * 2);
    assert_close(-2, r.d.z, 0);
    /* The last pixel (319, 179) mirrors it */
    r = camera_ray(&cam, (real)(319.5 / 320), (real)(179.5 / 180));
    assert_close(1.99375, r.d.x, 4 * EPS * 2);
    assert_close(1.11875, r.d.y, 4 * EPS * 2);
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
    expect_orthonormal_right_handed(make(steep));
    /* An orthographic camera needs no projDistance */
    scene_camera ortho = perspective(o, dir, up, 0, 1, 1);
    ortho.kind = CAMERA_ORTHOGRAPHIC;
    make(ortho);
}

static const graded_test tests[] = {
    GRADED(test_basis_orthonormal_right_handed, 3),
    GRADED(test_basis_of_axis_camera_is_exact, 1),
    GRADED(test_centre_ray_along_view_dir, 2),
    GRADED(test_four_corner_rays_exactly, 2),
    GRADED(test_projection_distance_scales_the_view, 1),
    GRADED(test_orthographic_rays_parallel_from_image_plane, 3),
    GRADED(test_pixel_centres_of_non_square_image, 2),
    GRADED(test_degenerate_cameras_rejected, 1),
};
SUITE_MAIN("01_camera_rays", tests)
