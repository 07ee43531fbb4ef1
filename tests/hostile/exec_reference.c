/* Hostile submission for chapter 05 (tools/hostile.sh): lambert runs the
 * reference's suite in its own place, with its own test name, seed and
 * descriptor 3 (read from /proc/self/cmdline), so that the reference writes
 * the records the grader expects.  The grader's suites are copies named
 * suite-N side by side; it tries the one after its own.  lambert returns
 * zeros when that fails. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    char self[512] = "", args[4096];
    FILE *f = fopen("/proc/self/cmdline", "rb");
    size_t len = f ? fread(args, 1, sizeof args - 1, f) : 0;
    if (f)
        fclose(f);
    args[len] = '\0';
    char *argv[16];
    int argc = 0;
    for (size_t k = 0; k < len && argc < 15; k += strlen(args + k) + 1)
        argv[argc++] = args + k;
    argv[argc] = NULL;
    ssize_t got = readlink("/proc/self/exe", self, sizeof self - 1);
    char *dash = got > 0 ? strrchr(self, '-') : NULL;
    if (!dash || argc < 7)
        return color_make(0, 0, 0);
    int index = 0;
    if (sscanf(dash + 1, "%d", &index) == 1) {
        snprintf(dash + 1, sizeof self - (size_t)(dash + 1 - self), "%d", index + 1);
        argv[0] = self;
        execv(self, argv);
    }
    return color_make(0, 0, 0);
}
