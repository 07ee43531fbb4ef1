/* common/surface_attributes.h: the mesh face a point lies on, a sphere's (u, v). */
#include "suite.h"
#include "surface_attributes.h"

/* A scene by hand: surface 0 a Sphere, 1 the second Mesh, 2 a Triangle. */
static mesh_face faces[2] = {{.v = {0, 1, 2}, .vt = {-1, -1, -1}}, {.v = {2, 1, 0}, .vt = {0, 1, 2}}};
static mesh meshes[2] = {{.n_faces = 0}, {.faces = faces, .n_faces = 2}};
static scene_surface surfaces[3] = {
    {.kind = SURFACE_SPHERE, .center = {1, 2, 3}, .radius = 2},
    {.kind = SURFACE_MESH, .mesh = 1},
    {.kind = SURFACE_TRIANGLE},
};
static const scene desc = {.surfaces = surfaces, .n_surfaces = 3, .meshes = meshes, .n_meshes = 2};

/* The face of a Mesh surface is its own mesh's, by address; other surfaces have none. */
static void test_mesh_face(void **state)
{
    (void)state;
    const mesh *m = NULL;
    assert_ptr_equal(&faces[1], surface_mesh_face(&desc, 1, 1, &m));
    assert_ptr_equal(&meshes[1], m);
    assert_ptr_equal(&faces[0], surface_mesh_face(&desc, 1, 0, &m));
    m = NULL;
    assert_null(surface_mesh_face(&desc, 0, 0, &m));
    assert_null(surface_mesh_face(&desc, 2, 0, &m));
    assert_null(m);
}

/* A Sphere's (u, v) is sphere_uv's: the point on +z of the center is u = 1/2
 * (atan2(0, 1) = 0), v = 1/2 (asin(0) = 0), exactly; other surfaces give none. */
static void test_sphere_uv(void **state)
{
    (void)state;
    mesh_uv uv = {-1, -1};
    assert_true(surface_sphere_uv(&desc, 0, vec3_make(1, 2, 5), &uv));
    assert_true(uv.u == (real)0.5 && uv.v == (real)0.5);
    /* the north pole: v = 1/2 + asin(1) / pi, within a few roundings of 1 */
    assert_true(surface_sphere_uv(&desc, 0, vec3_make(1, 4, 3), &uv));
    assert_close(1, uv.v, 4 * REAL_EPSILON);
    uv = (mesh_uv){-1, -1};
    assert_false(surface_sphere_uv(&desc, 1, vec3_make(1, 2, 5), &uv));
    assert_false(surface_sphere_uv(&desc, 2, vec3_make(1, 2, 5), &uv));
    assert_true(uv.u == -1 && uv.v == -1);
}

static const graded_test tests[] = {
    GRADED(test_mesh_face, 0),
    GRADED(test_sphere_uv, 0),
};

SUITE_MAIN("common_surface_attributes", tests)
