/* self_hit.c - chapter 08's lab: does a convex mirror see itself?  Measured. */
#include "08_mirrors/lab/self_hit.h"

#include <math.h>

#include "08_mirrors/mirror.h"

const double self_hit_band_start[SELF_HIT_BANDS + 1] = {0, 60, 85, 89, 89.9, 89.99, 90};
const real self_hit_scales[SELF_HIT_SCALES] = {(real)1e-4, (real)1e-2, 1, (real)1e2, (real)1e4, (real)1e6, (real)1e8};

void self_hit_measure(real s, eps_policy policy, int n, self_hit_result *result)
{
    *result = (self_hit_result){{0}, {0}};
    const double pi = acos(-1.0);
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    vec3 c = vec3_scale(vec3_make((real)3.7, (real)2.9, (real)-4.3), s);
    if (surface_list_add_sphere(&list, (sphere){c, s}, -1, 0) < 0) {
        surface_list_free(&list);
        return;
    }
    vec3 D = vec3_normalize(vec3_make(-1, -2, -2)); /* the eye rays' direction */
    vec3 u = vec3_normalize(vec3_cross(D, vec3_make(0, 1, 0))), w = vec3_cross(u, D);
    for (int band = 0; band < SELF_HIT_BANDS; band++) {
        double from = self_hit_band_start[band], to = self_hit_band_start[band + 1];
        for (int k = 0; k < n; k++) {
            /* theta_i spread over the band, the side of the sphere turning with k */
            double theta = (from + (to - from) * (k + 0.5) / n) * pi / 180, phi = 2.399963 * k;
            vec3 side = vec3_add(vec3_scale(u, (real)cos(phi)), vec3_scale(w, (real)sin(phi)));
            vec3 start = vec3_add(vec3_sub(c, vec3_scale(D, 3 * s)), vec3_scale(side, s * (real)sin(theta)));
            ray r = {start, D};
            shading_point sp = {.r = r};
            if (!closest_hit_linear(&list, r, 0, REAL_INFINITY, &sp.hit))
                continue; /* a rounding at the very rim */
            sp.v = vec3_neg(vec3_normalize(r.d));
            sp.n = normal_towards_viewer(sp.hit.normal, r.d);
            ray mirror = spawn_ray(&sp, reflect(r.d, sp.n), policy);
            hit_record again;
            result->rays[band]++;
            result->hits[band] += closest_hit_linear(&list, mirror, 0, REAL_INFINITY, &again);
        }
    }
    surface_list_free(&list);
}
