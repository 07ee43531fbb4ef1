/* fresnel.c - chapter 09: how much a glass surface reflects. */
#include "09_refraction/fresnel.h"
#include "exercise.h"

#include <stddef.h>

const char *const fresnel_mode_names[] = {"exact", "schlick", NULL};

/* snippet: fresnel_exact */
real fresnel_exact(real cos_i, real cos_t, real eta_i, real eta_t)
{
    /* TODO fresnel: Fresnel's equations for unpolarised light:
     *     r_s = (eta_i cos_i - eta_t cos_t) / (eta_i cos_i + eta_t cos_t)
     *     r_p = (eta_t cos_i - eta_i cos_t) / (eta_t cos_i + eta_i cos_t)
     *     R = (r_s^2 + r_p^2) / 2 */
    EXERCISE_STUB("09_refraction", "fresnel.c", "fresnel"); /* delete this line when done */
    (void)cos_i;
    (void)cos_t;
    (void)eta_i;
    (void)eta_t;
    return 0;
}
/* end snippet */

/* snippet: fresnel_schlick */
real fresnel_schlick(real cos_i, real cos_t, real eta_i, real eta_t)
{
    /* TODO schlick: Schlick's approximation:
     *     R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2
     *     R = R_0 + (1 - R_0) (1 - cos)^5
     *     with cos the cosine on the side of the smaller index: cos_i when
     *     eta_i <= eta_t (into glass), cos_t otherwise (out of it). */
    EXERCISE_STUB("09_refraction", "fresnel.c", "schlick"); /* delete this line when done */
    (void)cos_i;
    (void)cos_t;
    (void)eta_i;
    (void)eta_t;
    return 0;
}
/* end snippet */

real fresnel(fresnel_mode mode, real cos_i, real cos_t, real eta_i, real eta_t)
{
    if (eta_i == eta_t) /* no change of index, no surface: nothing is reflected */
        return 0;
    return mode == FRESNEL_SCHLICK ? fresnel_schlick(cos_i, cos_t, eta_i, eta_t)
                                   : fresnel_exact(cos_i, cos_t, eta_i, eta_t);
}
