/* glass_limits.c - chapter 09's lab: where the build's precision gives out. */
#include "09_refraction/lab/glass_limits.h"

#include <math.h>

#include "06_shadows/spawn.h"
#include "09_refraction/refract.h"
#include "09_refraction/shade_glass.h"

static const double pi = 3.14159265358979323846;

/* A unit vector perpendicular to the unit vector n. */
static vec3 tangent_of(vec3 n)
{
    vec3 a = real_abs(n.x) < (real)0.6 ? vec3_make(1, 0, 0) : vec3_make(0, 1, 0);
    return vec3_normalize(vec3_sub(a, vec3_scale(n, vec3_dot(a, n))));
}

/* The k-th of `count` unit vectors spread over the sphere (a spiral). */
static vec3 spread(int k, int count)
{
    double z = 1 - (2.0 * k + 1) / count, r = sqrt(1 - z * z), phi = 2.399963229728653 * k;
    return vec3_make((real)(r * cos(phi)), (real)(r * sin(phi)), (real)z);
}

/* The angle between two directions, in radians (from the cross product,
 * accurate for small angles). */
static double angle_between(vec3 a, vec3 b)
{
    vec3 na = vec3_normalize(a), nb = vec3_normalize(b);
    double s = (double)vec3_length(vec3_cross(na, nb));
    return vec3_dot(na, nb) >= 0 ? asin(fmin(1, s)) : pi - asin(fmin(1, s));
}

/* The glass event where r meets the list's surfaces, with a shading point
 * as trace() builds it; false when it meets nothing. */
static bool meet(const surface_list *list, ray r, shading_point *sp, glass_event *e)
{
    *sp = (shading_point){.r = r};
    if (!closest_hit_linear(list, r, 0, REAL_INFINITY, &sp->hit))
        return false;
    sp->v = vec3_neg(vec3_normalize(r.d));
    sp->n = normal_towards_viewer(sp->hit.normal, r.d);
    *e = glass_at(sp, (real)1.5, FRESNEL_EXACT);
    return true;
}

static void equal_indices(FILE *out)
{
    const double angles[] = {0, 45, 80, 89, 89.9, 89.99, 89.999};
    fprintf(out, "# equal indices: build theta_i worst|T-d|\n");
    for (int a = 0; a < 7; a++) {
        double worst = 0;
        for (int k = 0; k < 1000; k++) {
            vec3 n = spread(k, 1000), t = tangent_of(n);
            double theta = angles[a] * pi / 180;
            vec3 d = vec3_add(vec3_scale(t, (real)sin(theta)), vec3_scale(n, (real)-cos(theta))), T;
            real cos_t;
            if (!refract(d, n, (real)1.33, (real)1.33, &T, &cos_t))
                worst = INFINITY;
            else
                worst = fmax(worst, (double)vec3_length(vec3_sub(T, d)));
        }
        fprintf(out, "eta_equal %s %g %.3g\n", REAL_NAME, angles[a], worst);
    }
}

static void critical_angle(FILE *out)
{
    /* out of glass of index 1.5: theta_c = asin(1/1.5); wrong decisions at
     * theta_c + delta for delta of either sign, checked down to 1e-12 */
    double theta_c = asin(1 / 1.5), worst = 0;
    for (int m = 1; m <= 12; m++)
        for (int sign = -1; sign <= 1; sign += 2)
            for (int k = 0; k < 200; k++) {
                double delta = sign * pow(10, -m) * (1 + k / 200.0);
                vec3 n = spread(k, 200), t = tangent_of(n);
                double theta = theta_c + delta;
                vec3 d = vec3_add(vec3_scale(t, (real)sin(theta)), vec3_scale(n, (real)-cos(theta))), T;
                real cos_t;
                bool transmits = refract(d, n, (real)1.5, 1, &T, &cos_t);
                if (transmits != (delta < 0) || (transmits && !(cos_t >= 0 && vec3_is_finite(T))))
                    worst = fmax(worst, fabs(delta));
            }
    fprintf(out, "# critical angle: build largest|theta-theta_c|_decided_wrongly_radians\n");
    fprintf(out, "critical %s %.3g\n", REAL_NAME, worst);
}

static void r_plus_t(FILE *out)
{
    double worst = 0;
    for (int way = 0; way < 2; way++)
        for (int k = 0; k < 9000; k++) {
            real eta_i = way ? (real)1.5 : 1, eta_t = way ? 1 : (real)1.5;
            double theta = 90.0 * k / 9000 * pi / 180;
            vec3 n = spread(k, 9000), t = tangent_of(n), T;
            vec3 d = vec3_add(vec3_scale(t, (real)sin(theta)), vec3_scale(n, (real)-cos(theta)));
            real cos_t, cos_i = -vec3_dot(d, n);
            if (!refract(d, n, eta_i, eta_t, &T, &cos_t))
                continue;
            real R = fresnel(FRESNEL_EXACT, cos_i, cos_t, eta_i, eta_t);
            real t_s = 2 * eta_i * cos_i / (eta_i * cos_i + eta_t * cos_t);
            real t_p = 2 * eta_i * cos_i / (eta_t * cos_i + eta_i * cos_t);
            real transmitted = eta_t * cos_t / (eta_i * cos_i) * (t_s * t_s + t_p * t_p) / 2;
            worst = fmax(worst, fabs((double)(R + transmitted) - 1));
        }
    fprintf(out, "# R + T = 1: build worst|R+T-1|\nr_plus_t %s %.3g\n", REAL_NAME, worst);
}

/* A ray into the glass and out again, refracted at both surfaces: true with
 * the second event e2 and where it left (sp2); false when it is lost,
 * reflected at either surface or not leaving through the far side. */
static bool pass_through(const surface_list *list, ray in, shading_point *sp2, glass_event *e2)
{
    shading_point sp1;
    glass_event e1;
    if (!meet(list, in, &sp1, &e1) || !e1.transmits || !meet(list, spawn_ray(&sp1, e1.T, EPS_BOUND), sp2, e2) ||
        !e2->transmits || vec3_dot(sp2->hit.normal, e1.T) <= 0)
        return false;
    return true;
}

static void sphere_centre(FILE *out)
{
    const real scales[] = {(real)1e-4, (real)1e-2, 1, (real)1e2, (real)1e4, (real)1e6, (real)1e8};
    fprintf(out, "# through the centre: build scale worst_angle_radians worst_distance/s lost\n");
    for (int k = 0; k < 7; k++) {
        real s = scales[k];
        vec3 c = vec3_scale(vec3_make((real)3.7, (real)2.9, (real)-4.3), s);
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
        if (surface_list_add_sphere(&list, (sphere){c, s}, -1, 0) < 0) {
            surface_list_free(&list);
            return;
        }
        double worst_angle = 0, worst_distance = 0;
        int lost = 0; /* rays that did not come out after two surfaces */
        for (int j = 0; j < 200; j++) {
            vec3 along = spread(j, 200);
            ray in = {vec3_sub(c, vec3_scale(along, 3 * s)), along};
            shading_point sp2;
            glass_event e2;
            if (!pass_through(&list, in, &sp2, &e2)) {
                lost++;
                continue;
            }
            worst_angle = fmax(worst_angle, angle_between(e2.T, along));
            vec3 to_c = vec3_sub(c, sp2.hit.point);
            worst_distance = fmax(worst_distance, (double)vec3_length(vec3_cross(to_c, e2.T)) / (double)s);
        }
        fprintf(out, "centre %s %g %.3g %.3g %d\n", REAL_NAME, (double)s, worst_angle, worst_distance, lost);
        surface_list_free(&list);
    }
}

static void slab(FILE *out)
{
    const real scales[] = {1, (real)1e4, (real)1e8};
    const double angles[] = {10, 45, 80, 89, 89.9};
    fprintf(out, "# slab: build scale theta_i worst_angle_radians lost\n");
    for (int k = 0; k < 3; k++)
        for (int a = 0; a < 5; a++) {
            real s = scales[k];
            vec3 c = vec3_scale(vec3_make((real)3.7, (real)2.9, (real)-4.3), s);
            surface_list list;
            surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
            /* the faces y = c.y and y = c.y - s, 10 s wide, normals out of the slab */
            real w = 10 * s, top = c.y, bottom = c.y - s;
            triangle up = {{c.x - w, top, c.z - w}, {c.x - w, top, c.z + w}, {c.x + 2 * w, top, c.z}};
            triangle down = {{c.x - w, bottom, c.z - w}, {c.x + 2 * w, bottom, c.z}, {c.x - w, bottom, c.z + w}};
            if (surface_list_add_triangle(&list, up, -1, 0) < 0 || surface_list_add_triangle(&list, down, -1, 1) < 0) {
                surface_list_free(&list);
                return;
            }
            double worst = 0;
            int lost = 0;
            for (int j = 0; j < 200; j++) {
                double theta = angles[a] * pi / 180, phi = 2 * pi * j / 200;
                vec3 d = {(real)(sin(theta) * cos(phi)), (real)-cos(theta), (real)(sin(theta) * sin(phi))};
                vec3 entry = vec3_add(c, vec3_scale(vec3_make((real)cos(j), 0, (real)sin(j)), s));
                ray in = {vec3_sub(entry, vec3_scale(d, s)), d};
                shading_point sp2;
                glass_event e2;
                if (!pass_through(&list, in, &sp2, &e2)) {
                    lost++;
                    continue;
                }
                worst = fmax(worst, angle_between(e2.T, d));
            }
            fprintf(out, "slab %s %g %g %.3g %d\n", REAL_NAME, (double)s, angles[a], worst, lost);
            surface_list_free(&list);
        }
}

void glass_limits(FILE *out)
{
    equal_indices(out);
    critical_angle(out);
    r_plus_t(out);
    sphere_centre(out);
    slab(out);
}
