/* degenerate_count.c - chapter 03's lab: false and lost hits, with rounded data. */
#include "03_triangle/lab/degenerate_count.h"

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

static placement random_placement(generator *g)
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
    for (int i = 0; i < 3; i++)
        p.offset[i] = distance * symmetric(g);
    return p;
}

static vec3 place(const placement *p, double x, double y, double z)
{
    double out[3];
    for (int i = 0; i < 3; i++)
        out[i] = p->offset[i] + p->scale * (p->m[i][0] * x + p->m[i][1] * y + p->m[i][2] * z);
    return vec3_make((real)out[0], (real)out[1], (real)out[2]);
}

/* The reference: Cramer's rule in long double on the same (rounded) data.
 * Returns the smallest of alpha, beta, gamma (negative outside) and t. */
static long double reference(const triangle *tri, ray r, long double *t)
{
    long double e1[3] = {(long double)tri->a.x - tri->b.x, (long double)tri->a.y - tri->b.y,
                         (long double)tri->a.z - tri->b.z};
    long double e2[3] = {(long double)tri->a.x - tri->c.x, (long double)tri->a.y - tri->c.y,
                         (long double)tri->a.z - tri->c.z};
    long double s[3] = {(long double)tri->a.x - r.p.x, (long double)tri->a.y - r.p.y,
                        (long double)tri->a.z - r.p.z};
    long double d[3] = {r.d.x, r.d.y, r.d.z};
#define DET(u, v, w)                                                                                               \
    ((u)[0] * ((v)[1] * (w)[2] - (v)[2] * (w)[1]) + (u)[1] * ((v)[2] * (w)[0] - (v)[0] * (w)[2]) +                  \
     (u)[2] * ((v)[0] * (w)[1] - (v)[1] * (w)[0]))
    long double M = DET(e1, e2, d);
    if (M == 0)
        return -1;
    long double beta = DET(s, e2, d) / M, gamma = DET(e1, s, d) / M;
    *t = DET(e1, e2, s) / M;
#undef DET
    long double least = beta < gamma ? beta : gamma;
    return 1 - beta - gamma < least ? 1 - beta - gamma : least;
}

static double distance_in_edges(ray r, real t, vec3 x, real edge)
{
    return (double)(vec3_length(vec3_sub(ray_at(r, t), x)) / edge);
}

degenerate_count degenerate_counts(long n, triangle_test test)
{
    degenerate_count c = {0};
    generator g = {88172645463325252u};
    /* The plane x + y + z = 0, by an (irrational, so rounded) orthonormal basis. */
    const vec3 e_u = vec3_make((real)(1 / sqrt(2.0)), (real)(-1 / sqrt(2.0)), 0);
    const vec3 e_v = vec3_make((real)(1 / sqrt(6.0)), (real)(1 / sqrt(6.0)), (real)(-2 / sqrt(6.0)));
    for (long i = 0; i < n; i++) {
        placement pl = random_placement(&g);
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
            long double t = 0;
            long double inside = reference(&tri, r, &t);
            if (inside > 0.01L && t > 1e-3L) {
                c.clear_hits++;
                c.lost_hits += !triangle_intersect(&tri, r, 0, REAL_INFINITY, test, &h);
            }
        }
    }
    return c;
}
