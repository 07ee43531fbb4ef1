/* Hostile submission for chapter 05 (tools/hostile.sh): writes files of 64
 * MiB each (the limit of a file's size) into its folder, /tmp and /var/tmp,
 * up to 4 GiB in all, and says how much it wrote.  A file's size was
 * limited, the number of files not: 5.6 GiB went to the machine's disk in a
 * test of 3 s (the disk of a test of 10 s and a budget of 1200 s filled so).
 * Each test must write at most 64 MiB.  lambert returns zeros. */
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
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
        const char *const folders[] = {".", "/tmp", "/var/tmp"};
        long mib = 0;
        for (int k = 0; k < 64; k++) {
            char name[64];
            snprintf(name, sizeof name, "%s/disk-fill-%d-%d", folders[k % 3], (int)getpid(), k);
            int fd = open(name, O_WRONLY | O_CREAT | O_TRUNC, 0600);
            if (fd < 0)
                continue;
            for (int b = 0; b < 64 && write(fd, block, sizeof block) == (ssize_t)sizeof block; b++)
                mib++;
            close(fd);
            fprintf(stderr, "disk fill: wrote %ld MiB\n", mib);
        }
    }
    return color_make(0, 0, 0);
}
