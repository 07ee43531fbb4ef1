/* cracks.c - chapter 03's lab: rays aimed at the edges and vertices of a closed mesh. */
#include "03_triangle/lab/cracks.h"

#include <stdint.h>

#include "03_triangle/scenes/icosahedron.h"

vec3 edge_point(vec3 e0, vec3 e1, real s) { return vec3_add(e0, vec3_scale(vec3_sub(e1, e0), s)); }

bool hits_any(const triangle *tris, int n, ray r, triangle_test test)
{
    triangle_hit hit;
    for (int k = 0; k < n; k++)
        if (triangle_intersect(&tris[k], r, 0, REAL_INFINITY, test, &hit))
            return true;
    return false;
}

bool near_edge(const triangle *tri, real beta, real gamma, real width, vec3 *e0, vec3 *e1, real *s)
{
    const real w[3] = {1 - beta - gamma, beta, gamma}; /* alpha, beta, gamma */
    const vec3 v[3] = {tri->a, tri->b, tri->c};
    int n_near = 0, k_near = 0, k_largest = 0;
    for (int k = 0; k < 3; k++) {
        if (w[k] < width) {
            n_near++;
            k_near = k;
        }
        if (w[k] > w[k_largest])
            k_largest = k;
    }
    if (n_near == 0)
        return false;
    if (n_near > 1) { /* near two edges: at their common vertex */
        *e0 = *e1 = v[k_largest];
        *s = 0;
        return true;
    }
    /* Near the edge opposite vertex k_near, between vertices i and j. */
    int i = (k_near + 1) % 3, j = (k_near + 2) % 3;
    *e0 = v[i];
    *e1 = v[j];
    *s = w[j] / (w[i] + w[j]);
    return true;
}

/* A number in [0, 1) from (k, axis): a fixed hash, so every run and every
 * platform gets the same origins. */
static real scatter(int k, int axis)
{
    uint32_t h = (uint32_t)k * 2654435761u + (uint32_t)axis * 40503u + 12345u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return (real)(h >> 8) / (real)(1u << 24);
}

vec3 crack_origin(vec3 centre, real radius, int k)
{
    if (k == 0)
        return centre;
    /* A point of the cube [-1, 1]^3 scaled by 0.45 radius: inside the inscribed
     * sphere, whose radius is about 0.79 of the vertices' distance. */
    vec3 q = vec3_make(2 * scatter(k, 0) - 1, 2 * scatter(k, 1) - 1, 2 * scatter(k, 2) - 1);
    return vec3_add(centre, vec3_scale(q, (real)0.45 * radius));
}

crack_count icosahedron_cracks(vec3 centre, real radius, int n_origins, int n_steps, triangle_test test)
{
    vec3 v[ICOSAHEDRON_VERTICES];
    triangle faces[ICOSAHEDRON_FACES];
    int edges[ICOSAHEDRON_EDGES][2];
    icosahedron_vertices(centre, radius, v);
    icosahedron_triangles(v, faces);
    icosahedron_edges(edges);

    crack_count count = {0, 0};
    for (int o = 0; o < n_origins; o++) {
        vec3 p = crack_origin(centre, radius, o);
        /* snippet: aim */
        for (int k = 0; k < ICOSAHEDRON_VERTICES; k++) { /* at the vertices */
            ray r = {p, vec3_sub(v[k], p)};
            count.rays++;
            count.misses += !hits_any(faces, ICOSAHEDRON_FACES, r, test);
        }
        for (int e = 0; e < ICOSAHEDRON_EDGES; e++) /* at points along the edges */
            for (int j = 1; j < n_steps; j++) {
                vec3 x = edge_point(v[edges[e][0]], v[edges[e][1]], (real)j / (real)n_steps);
                ray r = {p, vec3_sub(x, p)};
                count.rays++;
                count.misses += !hits_any(faces, ICOSAHEDRON_FACES, r, test);
            }
        /* end snippet */
    }
    return count;
}
