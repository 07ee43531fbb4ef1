/* triangle.h - chapter 03: where a ray meets a triangle (README, "The intersection"). */
#ifndef CH03_TRIANGLE_H
#define CH03_TRIANGLE_H

#include "watertight.h" /* the ray and the watertight test, given (common/) */

/* snippet: triangle */
typedef struct {
    vec3 a, b, c; /* the vertices; (b - a) x (c - a) is the front side's normal */
} triangle;

/* The triangle test knob, --triangle. */
typedef enum {
    TRIANGLE_CRAMER,     /* the lecture's 3x3 system by Cramer's rule (chapter 03's default) */
    TRIANGLE_WATERTIGHT, /* Woop, Benthin and Wald (2013), no cracks: the default from chapter 04 on */
} triangle_test;

typedef struct {
    real t;           /* the hit point is p + t d */
    real beta, gamma; /* ... and a + beta (b - a) + gamma (c - a); alpha = 1 - beta - gamma */
} triangle_hit;
/* end snippet */

/* The hit of r with tri in (t_min, t_max), edges closed, both sides; false when none or
 * when the data do not decide the crossing (crossing.h: a degenerate triangle, a ray in
 * or along its plane).  Never NaN; *hit is written only on a hit. */
bool triangle_intersect(const triangle *tri, ray r, real t_min, real t_max, triangle_test test, triangle_hit *hit);

/* Cramer's rule alone (the exercise), without that check: false for M = 0,
 * a non-finite M and a NaN t, beta or gamma. */
bool triangle_cramer(const triangle *tri, ray r, real t_min, real t_max, triangle_hit *hit);

/* The watertight test of tri (watertight.h) for a ray watertight_ray_make made. */
static inline bool watertight_ray_hit(const watertight_ray *wr, const triangle *tri, real t_min, real t_max,
                                      triangle_hit *hit)
{
    real out[3];
    if (!watertight_hit(wr, &tri->a, &tri->b, &tri->c, t_min, t_max, out))
        return false;
    *hit = (triangle_hit){out[0], out[1], out[2]};
    return true;
}

/* normalize((b - a) x (c - a)), the zero vector for a degenerate triangle. */
vec3 triangle_normal(const triangle *tri);

/* snippet: det3 */
/* det[c0 c1 c2] = c0 . (c1 x c2), the scalar triple product. */
static inline real det3(vec3 c0, vec3 c1, vec3 c2) { return vec3_dot(c0, vec3_cross(c1, c2)); }
/* end snippet */

#endif
