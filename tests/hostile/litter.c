/* Hostile submission for chapter 05 (tools/hostile.sh): each test leaves a
 * 16 MiB file in $HOME, $TMPDIR and every folder anyone may write (/tmp,
 * /var/tmp, /dev/shm, /run/lock), and first says whether one left by
 * an earlier test is there ("litter: found ...").  Nothing must carry over
 * from one test to the next, and nothing must stay behind after grading.
 * lambert returns zeros. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

/* Says whether dir/rt-litter is there (left by an earlier test). */
static void look(const char *dir, const char *what)
{
    char path[512];
    snprintf(path, sizeof path, "%s/rt-litter", dir ? dir : "/nonexistent");
    if (access(path, F_OK) == 0)
        fprintf(stderr, "litter: found %s from an earlier test (%s)\n", what, path);
}

/* Leaves dir/rt-litter, 16 MiB. */
static void leave(const char *dir)
{
    char path[512];
    snprintf(path, sizeof path, "%s/rt-litter", dir ? dir : "/nonexistent");
    FILE *f = fopen(path, "w");
    if (!f)
        return;
    static char block[1 << 20];
    memset(block, 'x', sizeof block);
    for (int k = 0; k < 16; k++)
        fwrite(block, 1, sizeof block, f);
    fclose(f);
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) { /* look everywhere first: HOME and TMPDIR may be one folder */
        done = 1;
        static const char *const shared[] = {"/tmp", "/var/tmp", "/dev/shm", "/run/lock"};
        look(getenv("HOME"), "HOME");
        look(getenv("TMPDIR"), "TMPDIR");
        for (size_t k = 0; k < sizeof shared / sizeof shared[0]; k++)
            look(shared[k], shared[k]);
        leave(getenv("HOME"));
        leave(getenv("TMPDIR"));
        for (size_t k = 0; k < sizeof shared / sizeof shared[0]; k++)
            leave(shared[k]);
    }
    return color_make(0, 0, 0);
}
