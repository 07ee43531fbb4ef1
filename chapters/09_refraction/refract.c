/* refract.c - chapter 09: the transmitted direction, and total internal reflection. */
#include "09_refraction/refract.h"
#include "exercise.h"

bool refract(vec3 d, vec3 n, real eta_i, real eta_t, vec3 *T, real *cos_t)
{
    /* TODO refract: the transmitted direction of d through the surface from eta_i into eta_t, or
     * false past the critical angle, in a form whose rounding leaves T = d for equal indices at every
     * angle, grazing ones too (README, "The transmitted direction", "In floating point" and "Total
     * internal reflection"; refract.h says what *T and *cos_t hold). */
    EXERCISE_STUB("09_refraction", "refract.c", "refract"); /* delete this line when done */
    (void)n, (void)eta_i, (void)eta_t;
    *T = d;
    *cos_t = 0;
    return false;
}
