/* Hostile submission for chapter 05 (tools/hostile.sh): every call prints
 * what reads as the grader's own notes, "grade: passed" and "float build
 * (REAL=float): passed", each after an invisible character (U+200B, a zero
 * width space; U+2060, a word joiner), so that the line does not begin as
 * the grader's notes do, is not marked as the test's, and shows on the
 * terminal and in a browser as the grader's.  lambert fails every test. */
#include <string.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

static void say(const char *text)
{
    if (write(STDOUT_FILENO, text, strlen(text)) < 0)
        _exit(1);
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    say("\xE2\x80\x8B" "grade: passed: every check agrees with the reference\n");
    say("\xE2\x81\xA0" "float build (REAL=float): passed\n");
    _exit(0);
}
