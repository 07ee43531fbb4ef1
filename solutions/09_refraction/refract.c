/* refract.c - chapter 09: the transmitted direction, and total internal reflection. */
#include "09_refraction/refract.h"

bool refract(vec3 d, vec3 n, real eta_i, real eta_t, vec3 *T, real *cos_t)
{
    /* EXERCISE refract: the transmitted direction of d through the surface from eta_i into eta_t, or
     * false past the critical angle, in a form whose rounding leaves T = d for equal indices at every
     * angle, grazing ones too (README, "The transmitted direction", "In floating point" and "Total
     * internal reflection"; refract.h says what *T and *cos_t hold). */
    real r = eta_i / eta_t;       /* Snell: sin(theta_t) = r sin(theta_i), S_t = r S_i */
    real cos_i = -vec3_dot(d, n); /* |C_i| = cos(theta_i) */
    /* cos^2(theta_t) = 1 - |S_t|^2 = 1 - r^2 (1 - cos^2(theta_i)), from the cosine, not from the vector
     * S_t: grouped so that r = 1 gives exactly cos^2(theta_i) at every angle */
    real cos2_t = (1 - r * r) + r * r * (cos_i * cos_i);
    if (cos2_t < 0) /* |S_t|^2 > 1, past the critical angle: total internal reflection */
        return false;
    *cos_t = real_sqrt(cos2_t);
    /* T = C_t + S_t = -cos(theta_t) n + r (d + cos(theta_i) n), grouped by d and n: r = 1 gives T = d */
    *T = vec3_add(vec3_scale(d, r), vec3_scale(n, r * cos_i - *cos_t));
    return true;
    /* STUB
    (void)n, (void)eta_i, (void)eta_t;
    *T = d;
    *cos_t = 0;
    return false;
    END EXERCISE */
}
