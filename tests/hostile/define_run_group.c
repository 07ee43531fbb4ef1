/* Hostile submission for chapter 05 (tools/hostile.sh): defines cmocka's
 * _cmocka_run_group_tests, which then runs no test and reports no failure.
 * lambert returns zeros. */
#include <stddef.h>

#include "05_lambert/lambert.h"

int _cmocka_run_group_tests(const char *name, const void *tests, size_t n, void *setup, void *teardown);
int _cmocka_run_group_tests(const char *name, const void *tests, size_t n, void *setup, void *teardown)
{
    (void)name, (void)tests, (void)n, (void)setup, (void)teardown;
    return 0;
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    return color_make(0, 0, 0);
}
