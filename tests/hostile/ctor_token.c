/* Hostile submission for chapter 05 (tools/hostile.sh): a constructor that
 * reads the per-test token the grader passes on descriptor 3, writes back a
 * pass for it and exits before any test runs.  lambert itself returns zeros. */
#include <string.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

__attribute__((constructor)) static void forge(void)
{
    char token[80];
    ssize_t n = read(3, token, sizeof token - 1);
    if (n <= 0)
        return;
    token[n] = '\0';
    token[strcspn(token, "\n")] = '\0';
    char line[128];
    size_t len = strlen(token);
    memcpy(line, token, len);
    memcpy(line + len, " 0\n", 3);
    if (write(3, line, len + 3) > 0)
        _exit(0);
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    return color_make(0, 0, 0);
}
