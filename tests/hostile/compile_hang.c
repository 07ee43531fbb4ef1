/* Hostile submission for chapter 05 (tools/hostile.sh): a macro of the
 * assembler that calls itself twice, 40 deep, keeps the assembler busy for
 * ever in little memory.  The file holds assembly and is refused, but only
 * after it has been compiled, in the double and the float build: the
 * compile's time limit must be that of the grading's budget, not 120 s a
 * step outside it. */
#include "05_lambert/lambert.h"

__asm__(".macro spin n\n"
        ".if \\n\n"
        "spin \"(\\n-1)\"\n"
        "spin \"(\\n-1)\"\n"
        ".endif\n"
        ".endm\n"
        "spin 40\n");

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    return color_make(0, 0, 0);
}
