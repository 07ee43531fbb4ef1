/* Hostile submission for chapter 05 (tools/hostile.sh): lambert never
 * returns.  Each test stops at its time limit, and the whole run at the
 * grader's time budget. */
#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    for (volatile unsigned long k = 0;; k++) {
    }
}
