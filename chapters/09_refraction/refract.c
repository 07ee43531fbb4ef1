/* refract.c - chapter 09: the transmitted direction, and total internal reflection. */
#include "09_refraction/refract.h"
#include "exercise.h"

/* snippet: refract */
bool refract(vec3 d, vec3 n, real eta_i, real eta_t, vec3 *T, real *cos_t)
{
    /* TODO refract: the lecture's transmitted ray T = C_t + S_t:
     *     cos(theta_i) = -(d . n),  C_i = cos(theta_i) n,  S_i = d + C_i;
     *     Snell's law scales the sine part: S_t = (eta_i / eta_t) S_i;
     *     if |S_t|^2 > 1 there is no transmitted ray (total internal
     *     reflection): return false;
     *     otherwise cos(theta_t) = sqrt(1 - |S_t|^2), C_t = -cos(theta_t) n,
     *     *T = C_t + S_t, *cos_t = cos(theta_t), and return true. */
    EXERCISE_STUB("09_refraction", "refract.c", "refract"); /* delete this line when done */
    (void)n;
    (void)eta_i;
    (void)eta_t;
    *T = d;
    *cos_t = 0;
    return false;
}
/* end snippet */
