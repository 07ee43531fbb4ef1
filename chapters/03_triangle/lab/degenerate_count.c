/* degenerate_count.c - chapter 03's lab: false and lost hits, with rounded data. */
#include "03_triangle/lab/degenerate_count.h"

#include "03_triangle/lab/crossing_reference.h"

#include <math.h>
#include <stdint.h>

typedef struct {
    uint64_t state;
} generator;

static double uniform(generator *g) /* in [0, 1): xorshift64 */
{
    g->state ^= g->state << 13;
    g->state ^= g->state >> 7;
    g->state ^= g->state << 17;
    return (double)(g->state >> 11) / 9007199254740992.0;
}

static double symmetric(generator *g) { return 2 * uniform(g) - 1; }

/* A rotation (from a random unit quaternion), a scale and an offset: local
 * (x, y, z) becomes offset + scale R (x, y, z), computed in double and
 * rounded to real once. */
typedef struct {
    double m[3][3], scale, offset[3];
} placement;

/* Random: a scale from 1e-3 to 1e3 and, half of the time, a distance up to
 * 1e4 scales.  With fixed >= 0: scale 1 at that distance. */
static placement random_placement(generator *g, double fixed)
{
    double q[4], n = 0;
    for (int i = 0; i < 4; i++) {
        q[i] = symmetric(g);
        n += q[i] * q[i];
    }
    n = sqrt(n);
    double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    placement p = {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                    {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                    {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}},
                   pow(10, 6 * uniform(g) - 3),
                   {0, 0, 0}};
    double distance = uniform(g) < 0.5 ? 0 : pow(10, 4 * uniform(g)) * p.scale;
    double along[3] = {symmetric(g), symmetric(g), symmetric(g)};
    if (fixed >= 0) { /* along a random direction (the offsets' length is fixed) */
        p.scale = 1;
        distance = fixed / sqrt(along[0] * along[0] + along[1] * along[1] + along[2] * along[2]);
    }
    for (int i = 0; i < 3; i++)
        p.offset[i] = distance * along[i];
    return p;
}

static vec3 place(const placement *p, double x, double y, double z)
{
    double out[3];
    for (int i = 0; i < 3; i++)
        out[i] = p->offset[i] + p->scale * (p->m[i][0] * x + p->m[i][1] * y + p->m[i][2] * z);
    return vec3_make((real)out[0], (real)out[1], (real)out[2]);
}

/* A hit that the data as stored do not have: its point is farther from the
 * triangle than 1 % of the triangle's longest edge (crossing_reference.h). */
static long is_false(const triangle *tri, ray r, triangle_hit h, degenerate_count *c)
{
    long double off = hit_distance(tri, r, h.t);
    c->worst_off = fmax(c->worst_off, (double)off);
    return off > 0.01L;
}

static double distance_in_edges(ray r, real t, vec3 x, real edge)
{
    return (double)(vec3_length(vec3_sub(ray_at(r, t), x)) / edge);
}

degenerate_count degenerate_counts(long n, triangle_test test) { return degenerate_counts_at(n, test, -1); }

degenerate_count degenerate_counts_at(long n, triangle_test test, double distance)
{
    degenerate_count c = {0};
    generator g = {88172645463325252u};
    /* The plane x + y + z = 0, by an (irrational, so rounded) orthonormal basis. */
    const vec3 e_u = vec3_make((real)(1 / sqrt(2.0)), (real)(-1 / sqrt(2.0)), 0);
    const vec3 e_v = vec3_make((real)(1 / sqrt(6.0)), (real)(1 / sqrt(6.0)), (real)(-2 / sqrt(6.0)));
    for (long i = 0; i < n; i++) {
        placement pl = random_placement(&g, distance);
        triangle_hit h;
        { /* 1. A degenerate triangle: the third vertex on the line ab, or equal to a or b. */
            double ax = symmetric(&g), ay = symmetric(&g), bx = symmetric(&g), by = symmetric(&g);
            double s = 2 * uniform(&g) - 0.5;
            vec3 a = place(&pl, ax, ay, 0), b = place(&pl, bx, by, 0);
            vec3 third = i % 4 == 0   ? place(&pl, ax + s * (bx - ax), ay + s * (by - ay), 0)
                         : i % 4 == 1 ? vec3_add(a, vec3_scale(vec3_sub(b, a), (real)s))
                         : i % 4 == 2 ? b
                                      : a;
            triangle tri = i & 4 ? (triangle){a, b, third} : (triangle){third, a, b};
            vec3 x = vec3_add(a, vec3_scale(vec3_sub(b, a), (real)uniform(&g)));
            vec3 p = place(&pl, 3 * symmetric(&g), 3 * symmetric(&g), 3 * symmetric(&g));
            ray r = {p, vec3_sub(x, p)};
            c.degenerate_rays++;
            if (triangle_intersect(&tri, r, 0, REAL_INFINITY, test, &h)) {
                c.degenerate_hits++;
                c.degenerate_false += is_false(&tri, r, h, &c);
                c.degenerate_worst = fmax(c.degenerate_worst, distance_in_edges(r, h.t, x, vec3_length(vec3_sub(b, a))));
            }
        }
        { /* 2. A ray in the plane x + y + z = 0 of the triangle, aimed inside it. */
            double spread = vec3_length(vec3_make((real)pl.offset[0], (real)pl.offset[1], (real)pl.offset[2]));
            double u0 = spread * symmetric(&g), v0 = spread * symmetric(&g);
            vec3 v[3];
            for (int k = 0; k < 3; k++)
                v[k] = vec3_add(vec3_scale(e_u, (real)(u0 + pl.scale * symmetric(&g))),
                                vec3_scale(e_v, (real)(v0 + pl.scale * symmetric(&g))));
            triangle tri = {v[0], v[1], v[2]};
            double beta = uniform(&g), gamma = uniform(&g) * (1 - beta);
            vec3 x = vec3_add(tri.a, vec3_add(vec3_scale(vec3_sub(tri.b, tri.a), (real)beta),
                                              vec3_scale(vec3_sub(tri.c, tri.a), (real)gamma)));
            vec3 p = vec3_add(vec3_scale(e_u, (real)(u0 + 3 * pl.scale * symmetric(&g))),
                              vec3_scale(e_v, (real)(v0 + 3 * pl.scale * symmetric(&g))));
            ray r = {p, vec3_sub(x, p)};
            c.plane_rays++;
            if (triangle_intersect(&tri, r, 0, REAL_INFINITY, test, &h)) {
                c.plane_hits++;
                c.plane_false += is_false(&tri, r, h, &c);
                c.plane_worst = fmax(c.plane_worst, distance_in_edges(r, h.t, x, vec3_length(vec3_sub(tri.b, tri.a))));
            }
        }
        { /* 3. A proper triangle, a ray from up to 3 sizes away, aimed at a point
           *    near or in it, at heights from 3 down to 3e-8 sizes (grazing). */
            vec3 a = place(&pl, symmetric(&g), symmetric(&g), 0.3 * symmetric(&g));
            vec3 b = place(&pl, symmetric(&g), symmetric(&g), 0.3 * symmetric(&g));
            vec3 cc = place(&pl, symmetric(&g), symmetric(&g), 0.3 * symmetric(&g));
            triangle tri = {a, b, cc};
            double beta = 1.4 * uniform(&g) - 0.2, gamma = 1.4 * uniform(&g) - 0.2;
            vec3 x = vec3_add(a, vec3_add(vec3_scale(vec3_sub(b, a), (real)beta), vec3_scale(vec3_sub(cc, a), (real)gamma)));
            double height = 3 * pow(10, -8 * uniform(&g)) * (uniform(&g) < 0.5 ? 1 : -1);
            vec3 p = place(&pl, 3 * symmetric(&g), 3 * symmetric(&g), height);
            ray r = {p, vec3_sub(x, p)};
            crossing ref;
            /* Clear: 1 % inside, and decided by the arithmetic: Cramer's rule
             * in real without the check puts the point within 1/1024 of the
             * longest edge of where the data put it. */
            if (crossing_reference(&tri, r, &ref) && ref.least > 0.01L && ref.t > 1e-3L &&
                triangle_cramer(&tri, r, 0, REAL_INFINITY, &h) && hit_error(&tri, r, h, &ref) <= 1.0L / 1024) {
                c.clear_hits++;
                c.lost_hits += !triangle_intersect(&tri, r, 0, REAL_INFINITY, test, &h);
            }
        }
    }
    return c;
}
