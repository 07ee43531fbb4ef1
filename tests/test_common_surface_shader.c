/* common/surface_shader.h: the shader a surface of a scene is shaded with. */
#include "scene_build.h"
#include "suite.h"
#include "surface_shader.h"

/* A surface's own shader is the scene's, not a copy. */
static void test_own_shader(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    scene_add_shader(&desc, scene_default_shader(SHADER_PHONG));
    scene_add_shader(&desc, scene_default_shader(SHADER_RGB_NORMALS));
    assert_ptr_equal(&desc.shaders[0], surface_shader(&desc, 0));
    assert_ptr_equal(&desc.shaders[1], surface_shader(&desc, 1));
    scene_free(&desc);
}

/* Without a shader: white Lambertian with every default of docs/scenes.md
 * (copied constants: compared exactly). */
static void test_no_shader_is_white_lambertian(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    const scene_shader *white = surface_shader(&desc, -1);
    const color k_d = white->diffuse_color, k_s = white->specular_color, k_m = white->mirror_coefficient;
    assert_int_equal(SHADER_LAMBERTIAN, white->kind);
    assert_true(k_d.r == 1 && k_d.g == 1 && k_d.b == 1);
    assert_true(k_s.r == 1 && k_s.g == 1 && k_s.b == 1);
    assert_true(k_m.r == 0 && k_m.g == 0 && k_m.b == 0);
    assert_true(white->exponent == 1);
    assert_true(white->refractive_index == (real)1.5);
    assert_int_equal(-1, white->texture);
    assert_null(white->name);
    scene_free(&desc);
}

static const graded_test tests[] = {
    GRADED(test_own_shader, 0),
    GRADED(test_no_shader_is_white_lambertian, 0),
};

SUITE_MAIN("common_surface_shader", tests)
