/* sphere.c - chapter 02: the ray-sphere intersection, two ways.
 *
 * Notation (README.md, equations (1)-(5)): the ray is p + t d, the sphere has
 * centre c and radius R, and f = p - c is the ray's origin seen from the
 * centre.  Putting x = p + t d into (x - c).(x - c) - R^2 = 0 gives
 *     A t^2 + 2 B t + C = 0,   A = d.d,  B = d.f,  C = f.f - R^2      (1)
 * Both formulas below return its two roots; sphere_nearest_root() picks one.
 */
#include "02_sphere/sphere.h"
#include "exercise.h"

/* The lecture's algebraic solution, for any d (not only a unit d):
 *     t = (-d.f -+ sqrt((d.f)^2 - (d.d)(f.f - R^2))) / (d.d)          (2)
 * Returns false when the discriminant is negative (the ray misses). */
static bool textbook_roots(const sphere *s, ray r, real *t0, real *t1)
{
    /* TODO textbook: the lecture's quadratic formula (2), "Ray-sphere intersection: algebraic".
     *     f = p - c,  A = d.d,  B = d.f,  C = f.f - R^2,  discriminant B^2 - A C
     *     no root when the discriminant is negative (or NaN: test !(disc >= 0));
     *     else t0 = (-B - sqrt(disc)) / A,  t1 = (-B + sqrt(disc)) / A */
    EXERCISE_STUB("02_sphere", "sphere.c", "textbook"); /* delete this line when done */
    (void)s;
    (void)r;
    *t0 = *t1 = 0;
    return false;
}

/* The same roots, computed so that they keep their digits:
 *   - the discriminant from the lecture's geometric form (3)-(4): the
 *     perpendicular l from the centre to the line is formed first, and
 *     R^2 - l.l no longer subtracts two huge, nearly equal numbers;
 *   - the roots from the stable pair (5): the one of larger magnitude by
 *     adding numbers of the same sign, the other from the product of the
 *     roots, t0 t1 = C / A (Vieta), so neither cancels. */
/* snippet: robust */
static bool robust_roots(const sphere *s, ray r, real *t0, real *t1)
{
    vec3 f = vec3_sub(r.p, s->center);
    real A = vec3_dot(r.d, r.d);
    real B = vec3_dot(r.d, f);
    /* TODO robust_discriminant: the discriminant from the geometric form, "Ray-sphere intersection: geometric".
     *     t_m = -B / A                the parameter of the point of the line closest to c      (3)
     *     l = f + t_m d               the perpendicular from c to the line, |l| = l_m
     *     disc = A (R^2 - l.l)        equal to B^2 - A C, without its cancellation             (4)
     * Keep l as a vector: l.l is small when the ray passes near c, B^2 and A C are not. */
    EXERCISE_STUB("02_sphere", "sphere.c", "robust_discriminant"); /* delete this line when done */
    (void)f;
    (void)B;
    real disc = -1;
    if (!(disc >= 0)) /* a miss, or NaN from d = 0 */
        return false;
    /* TODO robust_roots: the stable pair of roots (5)
     *     q = -(B + sign(B) sqrt(disc))    B and sign(B) sqrt(disc) have the same sign: no cancellation
     *     t0 = q / A,  t1 = C / q          (C = f.f - R^2; when q = 0 both roots are 0: t1 = t0)
     *     |t1| at most sqrt(|C| / A)       (else t1 = that, with t1's sign)                      (6)
     * (6): q^2 >= A |C| in exact arithmetic (q^2 >= B^2 >= A C, or q^2 >= disc >= -A C), so |C / q|
     * is at most sqrt(|C| / A).  Rounding breaks that by a few ulps where it is nearly tight, and
     * without limit where B, disc and C are all rounding noise (a ray along the tangent at a point
     * of the sphere): C / q is then noise of any size, a hit far from the sphere.  Compare t1^2 A
     * with |C| (no square root unless it is too large).
     * sign(B) must be +1 or -1, also for B = 0 (a ray whose origin is the point of its line closest to c):
     * a sign(0) = 0 makes q = 0 there, and C / q a division by zero.
     * Which of t0, t1 is nearer depends on the sign of B; sphere_nearest_root() sorts them. */
    EXERCISE_STUB("02_sphere", "sphere.c", "robust_roots"); /* delete this line when done */
    (void)A;
    (void)disc;
    *t0 = *t1 = 0;
    return false;
}
/* end snippet */

static bool roots_of(const sphere *s, ray r, sphere_formula formula, real *t0, real *t1)
{
    return formula == SPHERE_TEXTBOOK ? textbook_roots(s, r, t0, t1) : robust_roots(s, r, t0, t1);
}

/* snippet: scaled */
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
/* end snippet */

/* snippet: normal */
vec3 sphere_normal(const sphere *s, vec3 x)
{
    /* TODO normal: the outward unit normal at the hit point x:
     *     n = (x - c) / |x - c|
     * |x - c| is R up to rounding; dividing by the computed length makes n a unit vector all the same.
     * x - c is never zero at a hit (it has length R), but guard it so that no NaN leaves this function. */
    EXERCISE_STUB("02_sphere", "sphere.c", "normal"); /* delete this line when done */
    (void)s;
    (void)x;
    return vec3_make(0, 0, 0);
}
/* end snippet */

/* snippet: nearest */
bool sphere_nearest_root(real t0, real t1, real t_min, real t_max, real *t)
{
    /* TODO nearest: the nearest root inside the open window (t_min, t_max), the lecture's
     * s.intersect(ray, tMin, tMax):
     *     near = min(t0, t1), far = max(t0, t1)        (the formulas do not sort them)
     *     the near root when t_min < near < t_max, else the far root when t_min < far < t_max, else none.
     * The window is open: a root equal to t_min or t_max is outside it.  So a ray that starts on the
     * sphere (a root t = 0 with t_min = 0) does not hit it again where it starts. */
    EXERCISE_STUB("02_sphere", "sphere.c", "nearest"); /* delete this line when done */
    (void)t0;
    (void)t1;
    (void)t_min;
    (void)t_max;
    (void)t;
    return false;
}
/* end snippet */

/* snippet: intersect */
bool sphere_intersect(const sphere *s, ray r, real t_min, real t_max, sphere_formula formula, real *t, vec3 *n)
{
    real t0, t1, hit;
    if (!sphere_roots(s, r, formula, &t0, &t1) || !sphere_nearest_root(t0, t1, t_min, t_max, &hit))
        return false;
    *t = hit;
    *n = sphere_normal(s, ray_at(r, hit));
    return true;
}
/* end snippet */
