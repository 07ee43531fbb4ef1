/* common/scene_shapes.h: the spheres and triangles a scene's surfaces stand for. */
#include <stdlib.h>
#include <string.h>

#include "scene_build.h"
#include "scene_shapes.h"
#include "suite.h"

/* The shapes handed to `add`, and a call that fails (-1: none). */
typedef struct {
    scene_shape shapes[32];
    int n, fail_at;
} taken;

static int take(void *context, const scene_shape *shape)
{
    taken *t = context;
    if (t->n == t->fail_at || t->n == 32)
        return -1;
    t->shapes[t->n++] = *shape;
    return t->n - 1;
}

/* Corners are copied, never computed: compared exactly. */
static void assert_same(vec3 expected, vec3 got)
{
    assert_true(expected.x == got.x && expected.y == got.y && expected.z == got.z);
}

/* A sphere, a triangle, a box and a mesh of two faces, as the reader makes them. */
static void one_of_each(scene *desc)
{
    scene_init(desc);
    scene_add_surface(desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = 2, .center = {1, 2, 3}, .radius = 0.5,
                                            .line = 7});
    scene_add_surface(desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = -1, .v0 = {0, 0, 0}, .v1 = {1, 0, 0},
                                            .v2 = {0, 1, 0}, .line = 8});
    scene_add_surface(desc, (scene_surface){.kind = SURFACE_BOX, .shader = 0, .min_pt = {-1, -2, -3},
                                            .max_pt = {4, 5, 6}, .line = 9});
    mesh m = {.n_positions = 4, .n_faces = 2};
    m.positions = malloc(4 * sizeof *m.positions);
    m.faces = malloc(2 * sizeof *m.faces);
    assert_non_null(m.positions);
    assert_non_null(m.faces);
    const vec3 p[4] = {{0, 0, -1}, {2, 0, -1}, {2, 2, -1}, {0, 2, -1}};
    memcpy(m.positions, p, sizeof p);
    m.faces[0] = (mesh_face){.v = {0, 1, 2}, .vt = {-1, -1, -1}, .vn = {-1, -1, -1}};
    m.faces[1] = (mesh_face){.v = {0, 2, 3}, .vt = {-1, -1, -1}, .vn = {-1, -1, -1}};
    scene_add_mesh(desc, m);
    scene_add_surface(desc, (scene_surface){.kind = SURFACE_MESH, .shader = 1, .mesh = 0, .line = 10});
}

/* Surface by surface in the file's order: 1 + 1 + 12 + 2 shapes, each with
 * its surface's shader and index and its own face number. */
static void test_shapes_in_file_order(void **state)
{
    (void)state;
    scene desc;
    one_of_each(&desc);
    taken t = {.fail_at = -1};
    char err[256] = "";
    assert_int_equal(0, scene_shapes(&desc, take, &t, err, sizeof err));
    assert_int_equal(1 + 1 + BOX_TRIANGLES + 2, t.n);
    const scene_shape *s = t.shapes;
    assert_true(s[0].is_sphere);
    assert_same(vec3_make(1, 2, 3), s[0].center);
    assert_true(s[0].radius == (real)0.5);
    assert_int_equal(2, s[0].shader);
    assert_int_equal(0, s[0].source);
    assert_int_equal(0, s[0].face);
    assert_false(s[1].is_sphere);
    assert_same(desc.surfaces[1].v0, s[1].v[0]);
    assert_same(desc.surfaces[1].v1, s[1].v[1]);
    assert_same(desc.surfaces[1].v2, s[1].v[2]);
    assert_int_equal(-1, s[1].shader);
    assert_int_equal(1, s[1].source);
    assert_int_equal(0, s[1].face);
    vec3 box[BOX_TRIANGLES][3];
    box_triangles(desc.surfaces[2].min_pt, desc.surfaces[2].max_pt, box);
    for (int f = 0; f < BOX_TRIANGLES; f++) {
        const scene_shape *b = &s[2 + f];
        assert_false(b->is_sphere);
        assert_int_equal(0, b->shader);
        assert_int_equal(2, b->source);
        assert_int_equal(f, b->face);
        for (int k = 0; k < 3; k++)
            assert_same(box[f][k], b->v[k]);
    }
    for (int f = 0; f < 2; f++) {
        const scene_shape *m = &s[2 + BOX_TRIANGLES + f];
        assert_false(m->is_sphere);
        assert_int_equal(1, m->shader);
        assert_int_equal(3, m->source);
        assert_int_equal(f, m->face);
        for (int k = 0; k < 3; k++)
            assert_same(desc.meshes[0].positions[desc.meshes[0].faces[f].v[k]], m->v[k]);
    }
    scene_free(&desc);
}

/* A box's corners are made of minPt's and maxPt's coordinates, and its two
 * triangles of each face share the face's diagonal. */
static void test_box_corners(void **state)
{
    (void)state;
    const vec3 lo = {-1, -2, -3}, hi = {4, 5, 6};
    vec3 box[BOX_TRIANGLES][3];
    box_triangles(lo, hi, box);
    for (int f = 0; f < BOX_TRIANGLES; f++) {
        for (int k = 0; k < 3; k++) {
            assert_true(box[f][k].x == lo.x || box[f][k].x == hi.x);
            assert_true(box[f][k].y == lo.y || box[f][k].y == hi.y);
            assert_true(box[f][k].z == lo.z || box[f][k].z == hi.z);
        }
        if (f % 2 == 1) { /* the pair's first corner q00 is shared, and so is the diagonal's far end q11 */
            assert_same(box[f - 1][0], box[f][0]);
            assert_true(memcmp(&box[f - 1][1], &box[f][2], sizeof(vec3)) == 0 ||
                        memcmp(&box[f - 1][2], &box[f][1], sizeof(vec3)) == 0);
        }
    }
}

/* When add fails, scene_shapes stops at once and names the surface's line. */
static void test_add_fails(void **state)
{
    (void)state;
    scene desc;
    one_of_each(&desc);
    taken t = {.fail_at = 5}; /* the box's fourth triangle */
    char err[256] = "";
    assert_int_equal(-1, scene_shapes(&desc, take, &t, err, sizeof err));
    assert_int_equal(5, t.n);
    assert_string_equal("built-in scene:9: out of memory for the surface list", err);
    scene_free(&desc);
}

static const graded_test tests[] = {
    GRADED(test_shapes_in_file_order, 0),
    GRADED(test_box_corners, 0),
    GRADED(test_add_fails, 0),
};

SUITE_MAIN("common_scene_shapes", tests)
