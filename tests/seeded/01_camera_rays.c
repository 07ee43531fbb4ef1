/* Chapter 01's checks of inputs drawn at grading time (tests/answers.h):
 * pixel_to_image, camera_basis and camera_ray at pixels, view vectors and
 * cameras drawn from the grader's seed, against the reference's answers.
 * Each is a few roundings of values of the size of its inputs: two correct
 * formulas differ by a few REAL_EPSILON of that size; 64 leaves room. */
#include "01_camera_rays/camera.h"
#include "01_camera_rays/pixel.h"
#include "seeded.h"

static void seeded_pixel(unsigned long *rng)
{
    for (int k = 0; k < 8; k++) {
        int nx = 1 + (int)seeded_between(rng, 0, 2000), ny = 1 + (int)seeded_between(rng, 0, 2000);
        int i = (int)seeded_between(rng, 0, nx), j = (int)seeded_between(rng, 0, ny);
        real du = (real)suite_uniform(rng), dv = (real)suite_uniform(rng);
        real u, v;
        pixel_to_image(i, j, nx, ny, du, dv, &u, &v);
        const char *in = describe("pixel_to_image(%d, %d, %d, %d, %.9g, %.9g)", i, j, nx, ny, du, dv);
        suite_answer(describe("%s: u", in), u, 64 * REAL_EPSILON);
        suite_answer(describe("%s: v", in), v, 64 * REAL_EPSILON);
    }
}

static void seeded_basis(unsigned long *rng)
{
    for (int k = 0; k < 8; k++) {
        vec3 dir = vec3_scale(suite_random_unit(rng), (real)pow(10, seeded_between(rng, -1, 2)));
        vec3 up = vec3_scale(seeded_at_angle(rng, vec3_normalize(dir), seeded_between(rng, 0.3, 2.8)),
                             (real)pow(10, seeded_between(rng, -1, 2)));
        vec3 u, v, w;
        camera_basis(dir, up, &u, &v, &w);
        const char *in = describe("camera_basis(view_dir (%.9g, %.9g, %.9g), view_up (%.9g, %.9g, %.9g))", dir.x,
                                  dir.y, dir.z, up.x, up.y, up.z);
        suite_answer_vec3(describe("%s: u", in), u, 64 * REAL_EPSILON);
        suite_answer_vec3(describe("%s: v", in), v, 64 * REAL_EPSILON);
        suite_answer_vec3(describe("%s: w", in), w, 64 * REAL_EPSILON);
    }
}

/* A camera of the given kind with a random orthonormal basis (made here, not
 * by camera_basis, so that camera_ray is checked alone), eye and image. */
static camera random_camera(unsigned long *rng, camera_kind kind)
{
    vec3 w = suite_random_unit(rng);
    vec3 u = seeded_at_angle(rng, w, acos(0.0));
    camera cam = {.kind = kind, .e = seeded_point(rng, 50), .u = u, .v = vec3_cross(w, u), .w = w,
                  .d = (real)seeded_between(rng, 0.5, 5), .width = (real)seeded_between(rng, 0.5, 8),
                  .height = (real)seeded_between(rng, 0.5, 8)};
    return cam;
}

static void answer_rays(unsigned long *rng, camera_kind kind)
{
    for (int k = 0; k < 6; k++) {
        camera cam = random_camera(rng, kind);
        real u = (real)suite_uniform(rng), v = (real)suite_uniform(rng);
        ray r = camera_ray(&cam, u, v);
        double size = 1 + vec3_length(cam.e) + cam.d + cam.width + cam.height;
        const char *in = describe("camera_ray(%s camera at (%.9g, %.9g, %.9g), d = %.9g, %.9g x %.9g, u = %.9g, "
                                  "v = %.9g)",
                                  kind == CAMERA_PERSPECTIVE ? "perspective" : "orthographic", cam.e.x, cam.e.y,
                                  cam.e.z, cam.d, cam.width, cam.height, u, v);
        suite_answer_vec3(describe("%s: p", in), r.p, 64 * REAL_EPSILON * size);
        suite_answer_vec3(describe("%s: d", in), r.d, 64 * REAL_EPSILON * size);
    }
}

static void seeded_perspective(unsigned long *rng) { answer_rays(rng, CAMERA_PERSPECTIVE); }
static void seeded_orthographic(unsigned long *rng) { answer_rays(rng, CAMERA_ORTHOGRAPHIC); }

SEEDED_CHECKS(SEEDED(test_pixel_centres, seeded_pixel), SEEDED(test_pixel_sample_offsets, seeded_pixel),
              SEEDED(test_pixel_centres_of_non_square_image, seeded_perspective),
              SEEDED(test_basis_lecture_camera, seeded_basis),
              SEEDED(test_basis_orthonormal_right_handed, seeded_basis),
              SEEDED(test_basis_of_axis_camera_is_exact, seeded_basis),
              SEEDED(test_basis_of_huge_and_tiny_vectors, seeded_basis),
              SEEDED(test_degenerate_cameras_rejected, seeded_basis),
              SEEDED(test_perspective_rays, seeded_perspective),
              SEEDED(test_centre_ray_along_view_dir, seeded_perspective),
              SEEDED(test_four_corner_rays_exactly, seeded_perspective),
              SEEDED(test_projection_distance_scales_the_view, seeded_perspective),
              SEEDED(test_orthographic_rays, seeded_orthographic),
              SEEDED(test_orthographic_rays_parallel_from_image_plane, seeded_orthographic))
