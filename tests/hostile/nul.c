/* Hostile submission for chapter 05 (tools/hostile.sh): lambert prints a NUL
 * byte first, then a line of its own: a grader that keeps a test's output as
 * a C string loses everything after that byte, its own note of why the test
 * failed (and the float build's verdict) too, in results.json and on the
 * terminal, and what the test printed before it can pass for the grader's
 * word.  lambert returns zeros. */
#include <stdio.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        fputs("grade: the reference's answers, not yet computed here, were taken as given (not counted)\n", stderr);
        fputc('\0', stderr);
        fputs("hidden\n", stderr);
    }
    return color_make(0, 0, 0);
}
