/* Hostile submission for chapter 05 (tools/hostile.sh): every call prints
 * four lines, then what reads as the grader's own notes ("grade: passed",
 * "float build (REAL=float): passed"), then a line with a right-to-left
 * override (U+202E, which turns the rest of its line around on screen) and
 * no newline, and ends the test (_exit): the grader's note of why the test
 * failed then followed on that very line, the fifth of the test's, past the
 * four the terminal shows, and turned around in a browser.  lambert fails
 * every test. */
#include <string.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

static void say(const char *text)
{
    if (write(STDERR_FILENO, text, strlen(text)) < 0)
        _exit(1);
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    say("computing the Lambert term\nchecking the normal\nchecking the light\nall checks done\n");
    say("grade: passed: every check agrees with the reference\nfloat build (REAL=float): passed\n");
    say("\xE2\x80\xAE" "done ");
    _exit(0);
}
