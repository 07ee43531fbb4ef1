/* fresnel_table.c - chapter 09's lab: R against the angle, for the plot. */
#include "09_refraction/lab/fresnel_table.h"

#include <math.h>

#include "09_refraction/fresnel.h"
#include "09_refraction/refract.h"

/* R at the surface y = 0 (normal +y on the incoming side) for a ray coming
 * down at theta from the normal; 1 past the critical angle.  With
 * schlick_cos_i, Schlick's polynomial in cos_i whichever way the ray goes. */
static real reflectance(double theta, real eta_i, real eta_t, fresnel_mode mode, int schlick_cos_i)
{
    vec3 n = {0, 1, 0};
    vec3 d = {(real)sin(theta), (real)-cos(theta), 0};
    real cos_i = -vec3_dot(d, n);
    vec3 T;
    real cos_t;
    if (!refract(d, n, eta_i, eta_t, &T, &cos_t))
        return 1;
    if (schlick_cos_i)
        return fresnel_schlick(cos_i, cos_i, eta_i, eta_t);
    return fresnel(mode, cos_i, cos_t, eta_i, eta_t);
}

int fresnel_table(FILE *out, real eta, int steps)
{
    const double pi = acos(-1.0);
    fprintf(out, "# angle in_exact in_schlick out_exact out_schlick out_schlick_cos_i (eta %g, %s)\n", (double)eta,
            REAL_NAME);
    for (int k = 0; k <= steps; k++) {
        double degrees = 90.0 * k / steps, theta = degrees * pi / 180;
        fprintf(out, "%.4f %.6f %.6f %.6f %.6f %.6f\n", degrees, (double)reflectance(theta, 1, eta, FRESNEL_EXACT, 0),
                (double)reflectance(theta, 1, eta, FRESNEL_SCHLICK, 0),
                (double)reflectance(theta, eta, 1, FRESNEL_EXACT, 0),
                (double)reflectance(theta, eta, 1, FRESNEL_SCHLICK, 0),
                (double)reflectance(theta, eta, 1, FRESNEL_SCHLICK, 1));
    }
    return 0;
}
