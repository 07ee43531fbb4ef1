/* fresnel.c - chapter 09: how much a glass surface reflects. */
#include "09_refraction/fresnel.h"

#include <stddef.h>

const char *const fresnel_mode_names[] = {"exact", "schlick", NULL};

real fresnel_exact(real cos_i, real cos_t, real eta_i, real eta_t)
{
    /* EXERCISE fresnel: Fresnel's reflectance R of unpolarised light from the two cosines and indices
     * (README, "How much is reflected: Fresnel"). */
    real r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    real r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    return (r_s * r_s + r_p * r_p) / 2;
    /* STUB
    (void)cos_i, (void)cos_t, (void)eta_i, (void)eta_t;
    return 0;
    END EXERCISE */
}

real fresnel_schlick(real cos_i, real cos_t, real eta_i, real eta_t)
{
    /* EXERCISE schlick: Schlick's approximation of R, with the cosine of the right side of the surface
     * (README, "How much is reflected: Fresnel"). */
    real r = (eta_i - eta_t) / (eta_i + eta_t);
    real R_0 = r * r;
    real m = 1 - (eta_i <= eta_t ? cos_i : cos_t);
    return R_0 + (1 - R_0) * m * m * m * m * m;
    /* STUB
    (void)cos_i, (void)cos_t, (void)eta_i, (void)eta_t;
    return 0;
    END EXERCISE */
}

real fresnel(fresnel_mode mode, real cos_i, real cos_t, real eta_i, real eta_t)
{
    if (eta_i == eta_t) /* no change of index, no surface: nothing is reflected */
        return 0;
    return mode == FRESNEL_SCHLICK ? fresnel_schlick(cos_i, cos_t, eta_i, eta_t)
                                   : fresnel_exact(cos_i, cos_t, eta_i, eta_t);
}
