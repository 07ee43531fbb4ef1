/* refract.c - chapter 09: the transmitted direction, and total internal reflection. */
#include "09_refraction/refract.h"

/* snippet: refract */
bool refract(vec3 d, vec3 n, real eta_i, real eta_t, vec3 *T, real *cos_t)
{
    /* EXERCISE refract: the transmitted direction of d through the surface from eta_i into eta_t, or
     * false past the critical angle (README, "The transmitted direction" and "Total internal
     * reflection"; refract.h says what *T and *cos_t hold). */
    real cos_i = -vec3_dot(d, n);
    vec3 C_i = vec3_scale(n, cos_i);           /* |C_i| = cos(theta_i), out of the surface */
    vec3 S_i = vec3_add(d, C_i);               /* |S_i| = sin(theta_i), along the surface */
    vec3 S_t = vec3_scale(S_i, eta_i / eta_t); /* Snell: sin(theta_t) = (eta_i / eta_t) sin(theta_i) */
    real sin2_t = vec3_length_squared(S_t);
    if (sin2_t > 1) /* past the critical angle: total internal reflection */
        return false;
    *cos_t = real_sqrt(1 - sin2_t);
    *T = vec3_sub(S_t, vec3_scale(n, *cos_t)); /* T = C_t + S_t, C_t = -cos(theta_t) n */
    return true;
    /* STUB
    (void)n;
    (void)eta_i;
    (void)eta_t;
    *T = d;
    *cos_t = 0;
    return false;
    END EXERCISE */
}
/* end snippet */
