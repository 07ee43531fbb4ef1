/* Hostile submission for chapter 05 (tools/hostile.sh): lambert prints, as
 * its test's message, terminal escape sequences: clear the screen, a score
 * table of its own with full marks, then text made invisible, so that the
 * grader's own table, printed after it, does not show in the terminal of
 * whoever grades by hand; tools/hostile.sh adds a line that makes the
 * compiler print an escape sequence as a warning.  It returns zeros. */
#include <stdio.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    fprintf(stderr, "\033[2J\033[H\nchapter                     tests   points\n"
                    "05_lambert                    9/9    14/14\ntotal                         9/9    14/14\n\033[8m\n");
    return color_make(0, 0, 0);
}
