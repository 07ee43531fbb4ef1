/* Hostile submission for chapter 05 (tools/hostile.sh): prints bytes that are
 * not UTF-8 (a lone continuation byte, an overlong encoding, a surrogate, a
 * code point above U+10FFFF, a sequence cut short) and control characters;
 * results.json must stay valid UTF-8 and valid JSON.  lambert returns zeros. */
#include <stdio.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        fputs("bad bytes: \x80 \xc0\xaf \xe0\x80\xaf \xed\xa0\x80 \xf4\x90\x80\x80 \xf8\x88\x80\x80\x80 "
              "\x1b[31m \x7f \"quoted\" \\ \xe2\x82\n",
              stderr);
    }
    return color_make(0, 0, 0);
}
