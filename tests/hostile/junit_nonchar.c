/* Hostile submission for chapter 05 (tools/hostile.sh): prints U+FFFE and
 * U+FFFF, well-formed UTF-8 (EF BF BE, EF BF BF) but characters that XML 1.0
 * does not allow anywhere in a document: the JUnit report (junit.xml), which
 * copied them into a test's text, could not be read by any XML parser, and a
 * CI system saw no results at all.  They must be replaced there, as a byte
 * that is not UTF-8 is.  lambert returns zeros. */
#include <stdio.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        fputs("not XML: \xef\xbf\xbe \xef\xbf\xbf\n", stderr);
    }
    return color_make(0, 0, 0);
}
