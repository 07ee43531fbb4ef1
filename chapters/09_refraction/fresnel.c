/* fresnel.c - chapter 09: how much a glass surface reflects. */
#include "09_refraction/fresnel.h"
#include "exercise.h"

#include <stddef.h>

const char *const fresnel_mode_names[] = {"exact", "schlick", NULL};

real fresnel_exact(real cos_i, real cos_t, real eta_i, real eta_t)
{
    /* TODO fresnel: Fresnel's reflectance R of unpolarised light from the two cosines and indices
     * (README, "How much is reflected: Fresnel"). */
    EXERCISE_STUB("09_refraction", "fresnel.c", "fresnel"); /* delete this line when done */
    (void)cos_i, (void)cos_t, (void)eta_i, (void)eta_t;
    return 0;
}

real fresnel_schlick(real cos_i, real cos_t, real eta_i, real eta_t)
{
    /* TODO schlick: Schlick's approximation of R, with the cosine of the right side of the surface
     * (README, "How much is reflected: Fresnel"). */
    EXERCISE_STUB("09_refraction", "fresnel.c", "schlick"); /* delete this line when done */
    (void)cos_i, (void)cos_t, (void)eta_i, (void)eta_t;
    return 0;
}

real fresnel(fresnel_mode mode, real cos_i, real cos_t, real eta_i, real eta_t)
{
    if (eta_i == eta_t) /* no change of index, no surface: nothing is reflected */
        return 0;
    return mode == FRESNEL_SCHLICK ? fresnel_schlick(cos_i, cos_t, eta_i, eta_t)
                                   : fresnel_exact(cos_i, cos_t, eta_i, eta_t);
}
