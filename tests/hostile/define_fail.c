/* Hostile submission for chapter 05 (tools/hostile.sh): defines cmocka's
 * _fail, so that the linker takes it over the library's and a failed check
 * goes on as if it had passed.  lambert returns zeros. */
#include "05_lambert/lambert.h"

void _fail(const char *file, int line);
void _fail(const char *file, int line) { (void)file, (void)line; }

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    return color_make(0, 0, 0);
}
