/* workload.c - bench-grid's mesh and rays: the same numbers for the grid and for Embree. */
#include "workload.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "mesh.h"

/* ---- the scene: float vertices and triangles ---------------------------------------- */

void load_obj(const char *path, float_mesh *fm)
{
    mesh m;
    char err[512];
    if (mesh_load(path, &m, err, sizeof err) != 0) {
        fprintf(stderr, "grid_vs_embree: %s\n", err);
        exit(1);
    }
    fm->n_v = m.n_positions;
    fm->n_tri = m.n_faces;
    fm->v = malloc((size_t)fm->n_v * 3 * sizeof *fm->v);
    fm->tri = malloc((size_t)fm->n_tri * 3 * sizeof *fm->tri);
    for (long k = 0; k < fm->n_v; k++) {
        fm->v[3 * k] = (float)m.positions[k].x;
        fm->v[3 * k + 1] = (float)m.positions[k].y;
        fm->v[3 * k + 2] = (float)m.positions[k].z;
    }
    for (long k = 0; k < fm->n_tri; k++)
        for (int j = 0; j < 3; j++)
            fm->tri[3 * k + j] = (unsigned)m.faces[k].v[j];
    mesh_free(&m);
}

/* A unit sphere of nu x nv quads in longitude and latitude: the pole rows
 * give one triangle per quad, the others two: 2 nu (nv - 1) triangles. */
void make_sphere(long wanted, float_mesh *fm)
{
    long nu = (long)sqrt((double)wanted), nv = wanted / (2 * nu) + 1;
    fm->n_v = nu * (nv + 1);
    fm->v = malloc((size_t)fm->n_v * 3 * sizeof *fm->v);
    fm->tri = malloc((size_t)(2 * nu * nv) * 3 * sizeof *fm->tri);
    const double pi = 3.14159265358979323846;
    for (long j = 0; j <= nv; j++)
        for (long i = 0; i < nu; i++) {
            double theta = pi * (double)j / (double)nv, phi = 2 * pi * (double)i / (double)nu;
            float *p = fm->v + 3 * (j * nu + i);
            p[0] = (float)(sin(theta) * cos(phi));
            p[1] = (float)cos(theta);
            p[2] = (float)(sin(theta) * sin(phi));
        }
    fm->n_tri = 0;
    for (long j = 0; j < nv; j++)
        for (long i = 0; i < nu; i++) {
            unsigned a = (unsigned)(j * nu + i), b = (unsigned)(j * nu + (i + 1) % nu);
            unsigned c = a + (unsigned)nu, d = b + (unsigned)nu;
            if (j != nv - 1) { /* not at the south pole, where c and d coincide */
                unsigned *t = fm->tri + 3 * fm->n_tri++;
                t[0] = a, t[1] = c, t[2] = d;
            }
            if (j != 0) { /* not at the north pole, where a and b coincide */
                unsigned *t = fm->tri + 3 * fm->n_tri++;
                t[0] = a, t[1] = d, t[2] = b;
            }
        }
}

vec3 mesh_vertex(const float_mesh *fm, unsigned k)
{
    return vec3_make(fm->v[3 * k], fm->v[3 * k + 1], fm->v[3 * k + 2]);
}

/* ---- the rays ------------------------------------------------------------------------ */

/* The bounding box of the mesh's vertices. */
void mesh_box(const float_mesh *fm, float lo[3], float hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = INFINITY;
        hi[a] = -INFINITY;
    }
    for (long k = 0; k < fm->n_v; k++)
        for (int a = 0; a < 3; a++) {
            lo[a] = fminf(lo[a], fm->v[3 * k + a]);
            hi[a] = fmaxf(hi[a], fm->v[3 * k + a]);
        }
}

/* A pinhole camera looking at the mesh's box from the front and a little
 * above, its view filled by the mesh; directions rounded to float. */
float_ray *make_rays(const float_mesh *fm, int size)
{
    float lo[3], hi[3];
    mesh_box(fm, lo, hi);
    double c[3], radius = 0;
    for (int a = 0; a < 3; a++) {
        c[a] = 0.5 * ((double)lo[a] + hi[a]);
        radius += 0.25 * ((double)hi[a] - lo[a]) * ((double)hi[a] - lo[a]);
    }
    radius = sqrt(radius);
    const double dir[3] = {0.25, 0.3, 1}, len = sqrt(0.25 * 0.25 + 0.3 * 0.3 + 1);
    double eye[3], w[3];
    for (int a = 0; a < 3; a++) {
        eye[a] = c[a] + 3 * radius * dir[a] / len;
        w[a] = -dir[a] / len;
    }
    /* right = w x up (up = +y), up' = right x w */
    double right[3] = {-w[2], 0, w[0]}, rl = sqrt(right[0] * right[0] + right[2] * right[2]);
    for (int a = 0; a < 3; a++)
        right[a] /= rl;
    double up[3] = {right[1] * w[2] - right[2] * w[1], right[2] * w[0] - right[0] * w[2],
                    right[0] * w[1] - right[1] * w[0]};
    const double s = 0.8 * radius / (3 * radius); /* the half-width of the view at distance 1 */
    float_ray *rays = malloc((size_t)size * size * sizeof *rays);
    for (int j = 0; j < size; j++)
        for (int i = 0; i < size; i++) {
            double u = 2 * (i + 0.5) / size - 1, v = 1 - 2 * (j + 0.5) / size;
            float_ray *r = &rays[(long)j * size + i];
            for (int a = 0; a < 3; a++) {
                r->o[a] = (float)eye[a];
                r->d[a] = (float)(w[a] + s * (u * right[a] + v * up[a]));
            }
        }
    return rays;
}

/* Incoherent rays: origins uniform in the mesh's box (many of them inside
 * the mesh, as the origins of shadow and reflected rays are), directions
 * uniform on the sphere; a fixed generator, so every run gets the same rays. */
float_ray *make_random_rays(const float_mesh *fm, long n)
{
    float lo[3], hi[3];
    mesh_box(fm, lo, hi);
    uint64_t state = 0x9E3779B97F4A7C15ull;
    float_ray *rays = malloc((size_t)n * sizeof *rays);
    for (long k = 0; k < n; k++) {
        double u[5];
        for (int q = 0; q < 5; q++) { /* xorshift64*, the top 53 bits */
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            u[q] = (double)((state * 0x2545F4914F6CDD1Dull) >> 11) * 0x1p-53;
        }
        double z = 2 * u[3] - 1, phi = 6.283185307179586 * u[4], s = sqrt(1 - z * z);
        const double dir[3] = {s * cos(phi), s * sin(phi), z};
        for (int a = 0; a < 3; a++) {
            rays[k].o[a] = (float)(lo[a] + u[a] * ((double)hi[a] - lo[a]));
            rays[k].d[a] = (float)dir[a];
        }
    }
    return rays;
}
