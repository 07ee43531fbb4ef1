/* Hostile submission for chapter 05 (tools/hostile.sh): every call tries to
 * take 2 GiB, 64 MiB at a time, touching each page, and says how much it got
 * ("memory: got N MiB").  The grader's memory limit must stop it well short.
 * lambert returns zeros. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        enum { CHUNK = 64 << 20 };
        void *chunks[32];
        int got = 0;
        while (got < 32 && (chunks[got] = malloc(CHUNK)) != NULL) {
            memset(chunks[got], 1, CHUNK);
            got++;
        }
        fprintf(stderr, "memory: got %d MiB\n", got * 64);
        while (got > 0)
            free(chunks[--got]);
    }
    return color_make(0, 0, 0);
}
