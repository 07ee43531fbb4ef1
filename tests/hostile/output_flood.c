/* Hostile submission for chapter 05 (tools/hostile.sh): a correct lambert
 * in the double build (a wrong one in the float build, whose output the
 * grader then shows too) whose first call starts two threads that write
 * control characters (U+0001) to stdout and stderr, one line without end,
 * for as long as the test runs: each becomes six bytes ("\u0001") in
 * results.json. */
#include <pthread.h>
#include <string.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

static void *flood(void *arg)
{
    static char junk[65536];
    memset(junk, 1, sizeof junk);
    for (;;)
        if (write((int)(long)arg, junk, sizeof junk) < 0)
            return NULL;
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    static int started;
    if (!started) {
        started = 1;
        pthread_t t;
        pthread_create(&t, NULL, flood, (void *)1L);
        pthread_create(&t, NULL, flood, (void *)2L);
    }
    if (sizeof(real) == sizeof(float))
        return color_make(0, 0, 0);
    vec3 to_light = vec3_sub(light->position, point);
    real r2 = vec3_length_squared(to_light);
    vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));
    real c = real_fmax(0, vec3_dot(n, l));
    return color_scale(color_mul(k_d, light->intensity), c / r2);
}
