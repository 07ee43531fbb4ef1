/* Hostile submission for chapter 05 (tools/hostile.sh): the first call
 * writes 64 MiB (the file size limit) into each of 32 memory files
 * (memfd_create: files of no folder, held in memory, outside the limit on
 * the address space, which counts only what is mapped), and says how much
 * it got ("memory: got N MiB"), which must stay within the test's limit of
 * 1024 MiB.  lambert returns zeros. */
#define _GNU_SOURCE /* memfd_create */
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

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
            int fd = memfd_create("rt-memory", 0);
            if (fd < 0)
                break;
            int k = 0;
            while (k < 64 && write(fd, block, sizeof block) == (ssize_t)sizeof block)
                k++;
            got += k; /* the descriptor stays open: the file lives as long as the test */
            if (k < 64)
                break;
        }
        fprintf(stderr, "memory: got %d MiB in memory files\n", got);
    }
    return color_make(0, 0, 0);
}
