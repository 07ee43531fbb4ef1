/* Hostile submission for chapter 05 (tools/hostile.sh): the first test
 * writes files of 64 MiB (the file size limit) into /dev/shm, a tmpfs held
 * in memory, 2 GiB in all, and says how much it got ("memory: got N MiB"):
 * memory outside the test's limit of 1024 MiB (RLIMIT_AS), as System V
 * shared memory was, which is refused.  lambert returns zeros. */
#include <stdio.h>
#include <string.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        static char block[1 << 20];
        memset(block, 'x', sizeof block);
        int got = 0;
        for (int f = 0; f < 32; f++) {
            char path[64];
            snprintf(path, sizeof path, "/dev/shm/rt-shm-%d", f);
            FILE *out = fopen(path, "w");
            if (!out)
                break;
            int k = 0;
            while (k < 64 && fwrite(block, 1, sizeof block, out) == sizeof block)
                k++;
            got += k;
            if (fclose(out) != 0 || k < 64)
                break;
        }
        fprintf(stderr, "memory: got %d MiB in /dev/shm\n", got);
    }
    return color_make(0, 0, 0);
}
