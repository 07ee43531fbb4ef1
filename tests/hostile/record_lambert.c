/* Linked into chapter 05's suite with -Wl,--wrap=lambert (tools/hostile.sh):
 * every call of lambert, its inputs and the reference's answer, is appended
 * to the file $RT_TABLE as one line of a C table.  That table is the "table"
 * attack: a lambert that knows the answers to the suite's published inputs
 * and nothing else. */
#include <stdio.h>
#include <stdlib.h>

#include "05_lambert/lambert.h"

color __real_lambert(color k_d, vec3 point, vec3 n, const scene_light *light);
color __wrap_lambert(color k_d, vec3 point, vec3 n, const scene_light *light);

color __wrap_lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    color L = __real_lambert(k_d, point, n, light);
    const char *path = getenv("RT_TABLE");
    FILE *f = path ? fopen(path, "a") : NULL;
    if (f) {
        const vec3 p = light->position;
        const color I = light->intensity;
        fprintf(f, "{{%a, %a, %a, %a, %a, %a, %a, %a, %a, %a, %a, %a, %a, %a, %a}, {%a, %a, %a}},\n",
                (double)k_d.r, (double)k_d.g, (double)k_d.b, (double)point.x, (double)point.y, (double)point.z,
                (double)n.x, (double)n.y, (double)n.z, (double)p.x, (double)p.y, (double)p.z, (double)I.r,
                (double)I.g, (double)I.b, (double)L.r, (double)L.g, (double)L.b);
        fclose(f);
    }
    return L;
}
