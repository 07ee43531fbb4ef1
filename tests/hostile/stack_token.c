/* Hostile submission for chapter 05 (tools/hostile.sh): no constructor;
 * lambert looks up the stack for a run of 32 hexadecimal digits (the
 * grader's per-test token), writes back a pass for it on descriptor 3 and
 * exits.  Without a token it returns zeros. */
#include <string.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

static int hex(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); }

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    volatile char here = 0;
    const char *p = (const char *)&here;
    for (long k = 0; k < 16384; k++) { /* the callers' frames lie above */
        int run = 0;
        while (run < 33 && hex(p[k + run]))
            run++;
        if (run == 32 && p[k + 32] == '\0' && (k == 0 || !hex(p[k - 1]))) {
            char line[40];
            memcpy(line, p + k, 32);
            memcpy(line + 32, " 0\n", 3);
            if (write(3, line, 35) == 35)
                _exit(0);
        }
    }
    return color_make(0, 0, 0);
}
