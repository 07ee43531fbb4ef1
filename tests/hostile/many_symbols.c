/* Hostile submission for chapter 05 (tools/hostile.sh): a correct lambert,
 * and 100000 global variables defined in plain C (a macro that pastes
 * digits, ten by ten).  The file is refused, as any global but lambert is,
 * but a check that looks at each symbol with a process of its own, and
 * names every one in its refusal, took minutes (as root, outside the
 * grading's time budget): 200 s for 100000, hours for the million that fit
 * the file size limit. */
#include "05_lambert/lambert.h"

#define D0(p) int p##0, p##1, p##2, p##3, p##4, p##5, p##6, p##7, p##8, p##9;
#define D1(p) D0(p##0) D0(p##1) D0(p##2) D0(p##3) D0(p##4) D0(p##5) D0(p##6) D0(p##7) D0(p##8) D0(p##9)
#define D2(p) D1(p##0) D1(p##1) D1(p##2) D1(p##3) D1(p##4) D1(p##5) D1(p##6) D1(p##7) D1(p##8) D1(p##9)
#define D3(p) D2(p##0) D2(p##1) D2(p##2) D2(p##3) D2(p##4) D2(p##5) D2(p##6) D2(p##7) D2(p##8) D2(p##9)
#define D4(p) D3(p##0) D3(p##1) D3(p##2) D3(p##3) D3(p##4) D3(p##5) D3(p##6) D3(p##7) D3(p##8) D3(p##9)
D4(v)

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    vec3 to_light = vec3_sub(light->position, point);
    real r2 = vec3_dot(to_light, to_light);
    real n_dot = vec3_dot(n, to_light); /* r cos(theta) */
    if (!(n_dot > 0))
        return color_make(0, 0, 0);
    real falloff = n_dot / (r2 * real_sqrt(r2)); /* cos(theta) / r^2 */
    return color_make(k_d.r * light->intensity.r * falloff, k_d.g * light->intensity.g * falloff,
                      k_d.b * light->intensity.b * falloff);
}
