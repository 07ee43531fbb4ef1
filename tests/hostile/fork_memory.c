/* Hostile submission for chapter 05 (tools/hostile.sh): the first call
 * starts three child processes, and each of the four takes 512 MiB, 64 MiB
 * at a time, touching each page: the memory limit (RLIMIT_AS) is one
 * process's, and a child has a limit of its own.  It says how much the four
 * got together ("memory: got N MiB"), which must stay within the test's
 * limit of 1024 MiB.  lambert returns zeros. */
#define _DEFAULT_SOURCE /* fork, pause */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

static int take(void) /* MiB taken and kept */
{
    enum { CHUNK = 64 << 20 };
    int got = 0;
    void *p;
    while (got < 8 * 64 && (p = malloc(CHUNK)) != NULL) {
        memset(p, 1, CHUNK);
        got += 64;
    }
    return got;
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        int report[2], children = 0;
        if (pipe(report) != 0)
            return color_make(0, 0, 0);
        for (int k = 0; k < 3; k++) {
            pid_t pid = fork();
            if (pid == 0) {
                int got = take();
                if (write(report[1], &got, sizeof got) != (ssize_t)sizeof got)
                    _exit(1);
                for (;;)
                    pause(); /* holds it */
            }
            children += pid > 0;
        }
        int total = take(), got;
        for (int k = 0; k < children && read(report[0], &got, sizeof got) == (ssize_t)sizeof got; k++)
            total += got;
        fprintf(stderr, "memory: got %d MiB in %d processes\n", total, children + 1);
    }
    return color_make(0, 0, 0);
}
