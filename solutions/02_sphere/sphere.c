/* sphere.c - chapter 02: the ray-sphere intersection, two ways.
 *
 * Notation (README.md, equations (1)-(6)): the ray is p + t d, the sphere has
 * centre c and radius R, and f = p - c is the ray's origin seen from the
 * centre.  Putting x = p + t d into (x - c).(x - c) - R^2 = 0 gives
 *     A t^2 + 2 B t + C = 0,   A = d.d,  B = d.f,  C = f.f - R^2      (1)
 * Both formulas below return its two roots; sphere_nearest_root() picks one.
 */
#include "02_sphere/sphere.h"

#include "explain.h"

/* The lecture's algebraic solution, for any d (not only a unit d):
 *     t = (-d.f -+ sqrt((d.f)^2 - (d.d)(f.f - R^2))) / (d.d)          (2)
 * Returns false when the discriminant is negative (the ray misses). */
static bool textbook_roots(const sphere *s, ray r, real *t0, real *t1)
{
    /* EXERCISE textbook: both roots of the quadratic (1) by the lecture's formula (2), or false when it has
     * no real root (README, "The equations"). */
    vec3 f = vec3_sub(r.p, s->center);
    real A = vec3_dot(r.d, r.d);
    real B = vec3_dot(r.d, f);
    real C = vec3_dot(f, f) - s->radius * s->radius;
    real disc = B * B - A * C;
    if (!(disc >= 0))
        return false;
    real root = real_sqrt(disc);
    *t0 = (-B - root) / A;
    *t1 = (-B + root) / A;
    return true;
    /* STUB
    (void)s, (void)r;
    *t0 = *t1 = 0;
    return false;
    END EXERCISE */
}

/* The same roots, computed so that they keep their digits:
 *   - the discriminant from the lecture's geometric form (3)-(4): the
 *     perpendicular l from the centre to the line is formed first, and
 *     R^2 - l.l no longer subtracts two huge, nearly equal numbers;
 *   - the roots from the stable pair (5): the one of larger magnitude by
 *     adding numbers of the same sign, the other from the product of the
 *     roots, t0 t1 = C / A (Vieta), so neither cancels. */
static bool robust_roots(const sphere *s, ray r, real *t0, real *t1)
{
    vec3 f = vec3_sub(r.p, s->center);
    real A = vec3_dot(r.d, r.d);
    real B = vec3_dot(r.d, f);
    /* EXERCISE robust_discriminant: the discriminant of (1) by the geometric form (3)-(4) (README, "The
     * equations" and "Why two formulas"). */
    vec3 l = vec3_add(f, vec3_scale(r.d, -B / A));
    real disc = A * (s->radius * s->radius - vec3_dot(l, l));
    /* STUB
    (void)f, (void)B;
    real disc = -1;
    END EXERCISE */
    if (!(disc >= 0)) /* a miss, or NaN from d = 0 */
        return false;
    /* EXERCISE robust_roots: the stable pair of roots (5) with the bound (6) on t1 (README, "The
     * equations", "Stable roots"; the Exercises section warns about B = 0). */
    real C = vec3_dot(f, f) - s->radius * s->radius;
    real root = real_sqrt(disc);
    real q = -(B + (B < 0 ? -root : root));
    *t0 = q / A;
    *t1 = q != 0 ? C / q : *t0;
    if (*t1 * *t1 * A > real_abs(C)) /* |t1| > sqrt(|C| / A): B, disc and C are all rounding noise */
        *t1 = real_copysign(real_sqrt(real_abs(C) / A), *t1);
    return true;
    /* STUB
    (void)A, (void)disc;
    *t0 = *t1 = 0;
    return false;
    END EXERCISE */
}

static bool roots_of(const sphere *s, ray r, sphere_formula formula, real *t0, real *t1)
{
    return formula == SPHERE_TEXTBOOK ? textbook_roots(s, r, t0, t1) : robust_roots(s, r, t0, t1);
}

/* Both formulas multiply up to four lengths (A (R^2 - l.l) is |d|^2 R^2 in
 * size), which overflows or underflows for data far from 1 (in float from
 * about 1e9 and 1e-9: real.h, REAL_SAFE_EXPONENT).  The roots do not depend
 * on the units: with p, c and R divided by 2^m and d by 2^k, the same point
 * has t / 2^(m - k).  A power of two moves only the exponents, so data of
 * any size are solved as data in the safe range round; data already there
 * are left as they are. */
bool sphere_roots(const sphere *s, ray r, sphere_formula formula, real *t0, real *t1)
{
    const int m = vec3_scale_exponent(vec3_make(vec3_max_abs(r.p), vec3_max_abs(s->center), s->radius));
    const int k = vec3_scale_exponent(r.d);
    if (m == 0 && k == 0)
        return roots_of(s, r, formula, t0, t1);
    const sphere scaled_s = {vec3_ldexp(s->center, -m), (real)ldexp(s->radius, -m)};
    const ray scaled_r = {vec3_ldexp(r.p, -m), vec3_ldexp(r.d, -k)};
    if (!roots_of(&scaled_s, scaled_r, formula, t0, t1))
        return false;
    *t0 = (real)ldexp(*t0, m - k);
    *t1 = (real)ldexp(*t1, m - k);
    return true;
}

vec3 sphere_normal(const sphere *s, vec3 x)
{
    /* EXERCISE normal: the outward unit normal at the hit point x (README, "Exercises": why not divide
     * by R), never NaN. */
    vec3 m = vec3_sub(x, s->center);
    real length = vec3_length(m);
    return length > 0 ? vec3_scale(m, 1 / length) : m;
    /* STUB
    (void)s, (void)x;
    return vec3_make(0, 0, 0);
    END EXERCISE */
}

bool sphere_nearest_root(real t0, real t1, real t_min, real t_max, real *t)
{
    /* EXERCISE nearest: the nearest of the two roots inside the open window (t_min, t_max), the
     * lecture's s.intersect(ray, tMin, tMax) (README, "The code"). */
    real near = real_fmin(t0, t1), far = real_fmax(t0, t1);
    if (near > t_min && near < t_max) {
        *t = near;
        return true;
    }
    if (far > t_min && far < t_max) { /* the near root is at or before t_min: p is inside the sphere */
        *t = far;
        return true;
    }
    return false;
    /* STUB
    (void)t0, (void)t1, (void)t_min, (void)t_max, (void)t;
    return false;
    END EXERCISE */
}

bool sphere_intersect(const sphere *s, ray r, real t_min, real t_max, sphere_formula formula, real *t, vec3 *n)
{
    real t0 = 0, t1 = 0, hit = 0;
    bool roots = sphere_roots(s, r, formula, &t0, &t1);
    bool found = roots && sphere_nearest_root(t0, t1, t_min, t_max, &hit);
    EXPLAIN(explain_sphere(s->center, s->radius, roots, t0, t1, t_min, t_max, found, hit));
    if (!found)
        return false;
    *t = hit;
    *n = sphere_normal(s, ray_at(r, hit));
    return true;
}
