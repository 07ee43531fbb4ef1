/* sphere_mesh.c - chapter 10: a coarse sphere as a mesh, and a texture made in code. */
#include "10_interpolation/scenes/sphere_mesh.h"

#include <math.h>
#include <stdlib.h>

/* The unit direction of ring i (0: the north pole, bands: the south pole),
 * segment j: u = j / segments, v = 1 - i / bands in the course's convention. */
static vec3 direction(int i, int j, int segments, int bands)
{
    static const double pi = 3.14159265358979323846;
    double theta = pi * i / bands, phi = 2 * pi * ((double)j / segments - 0.5);
    return vec3_make((real)(sin(theta) * sin(phi)), (real)cos(theta), (real)(sin(theta) * cos(phi)));
}

/* A corner's normal index: the vertex's own, or none. */
static int vn(bool normals, int vertex) { return normals ? vertex : -1; }

int sphere_mesh(mesh *m, vec3 center, real radius, int segments, int bands, bool normals)
{
    *m = (mesh){0};
    int rings = bands - 1; /* rings of vertices between the poles */
    m->n_positions = 2 + rings * segments;
    m->n_uvs = (bands + 1) * (segments + 1); /* a grid with the seam's column twice */
    m->n_faces = 2 * segments * rings;
    m->positions = malloc(sizeof *m->positions * (size_t)m->n_positions);
    m->uvs = malloc(sizeof *m->uvs * (size_t)m->n_uvs);
    m->faces = malloc(sizeof *m->faces * (size_t)m->n_faces);
    if (normals) {
        m->n_normals = m->n_positions;
        m->normals = malloc(sizeof *m->normals * (size_t)m->n_normals);
    }
    if (!m->positions || !m->uvs || !m->faces || (normals && !m->normals)) {
        mesh_free(m);
        return -1;
    }
    /* vertex 0 the north pole, 1 the south pole, then ring by ring */
    for (int k = 0; k < m->n_positions; k++) {
        int i = k == 0 ? 0 : k == 1 ? bands : 1 + (k - 2) / segments, j = k < 2 ? 0 : (k - 2) % segments;
        vec3 n = direction(i, j, segments, bands);
        m->positions[k] = vec3_add(center, vec3_scale(n, radius));
        if (normals)
            m->normals[k] = n;
    }
    for (int i = 0; i <= bands; i++)
        for (int j = 0; j <= segments; j++)
            m->uvs[i * (segments + 1) + j] = (mesh_uv){(real)j / (real)segments, 1 - (real)i / (real)bands};
    int f = 0;
    for (int i = 0; i < bands; i++) {
        for (int j = 0; j < segments; j++) {
            /* the corners of the quad between rings i and i + 1, segments j and j + 1 */
            int a = i == 0 ? 0 : 2 + (i - 1) * segments + j;
            int d = i == 0 ? 0 : 2 + (i - 1) * segments + (j + 1) % segments;
            int b = i + 1 == bands ? 1 : 2 + i * segments + j;
            int c = i + 1 == bands ? 1 : 2 + i * segments + (j + 1) % segments;
            int ta = i * (segments + 1) + j, td = ta + 1, tb = ta + segments + 1, tc = tb + 1;
            if (i + 1 < bands) /* a, b, c (at the north pole a = d is the pole) */
                m->faces[f++] = (mesh_face){{a, b, c}, {ta, tb, tc}, {vn(normals, a), vn(normals, b), vn(normals, c)}};
            if (i > 0) /* a, c, d (at the south pole b = c is the pole) */
                m->faces[f++] = (mesh_face){{a, c, d}, {ta, tc, td}, {vn(normals, a), vn(normals, c), vn(normals, d)}};
        }
    }
    return 0;
}

int globe_texture(texture_image *t, int width, int height, int square)
{
    t->width = width;
    t->height = height;
    t->rgb = malloc((size_t)width * (size_t)height * 3);
    if (!t->rgb)
        return -1;
    for (int y = 0; y < height; y++) {
        for (int x = 0; x < width; x++) {
            /* u from 0 at the left to 1 at the right; the top row is v = 1 */
            double u = (x + 0.5) / width;
            int j = y / square, half = square / 2 > 0 ? square / 2 : 1;
            /* sea, from dark at u = 0 to light at u = 1: where u runs, and its seam */
            unsigned char c[3] = {(unsigned char)(20 + 70 * u), (unsigned char)(60 + 100 * u),
                                  (unsigned char)(110 + 110 * u)};
            if (j == 0) /* north polar cap, v near 1 */
                c[0] = c[1] = c[2] = 245;
            else if (j == (height - 1) / square) /* south polar cap, v near 0 */
                c[0] = 120, c[1] = 60, c[2] = 150;
            else if (y >= height / 2 - half && y < height / 2 + half) /* the equator, v = 1/2 */
                c[0] = 235, c[1] = 195, c[2] = 50;
            else if (x / square == width / square / 2) /* the meridian at u = 1/2 */
                c[0] = 200, c[1] = 45, c[2] = 35;
            else if (x / square == 0) /* the meridian at u = 0 (and 1): the seam */
                c[0] = 40, c[1] = 150, c[2] = 60;
            else if (x % square == 0 || y % square == 0) /* the graticule */
                c[0] = 225, c[1] = 225, c[2] = 215;
            for (int k = 0; k < 3; k++)
                t->rgb[((size_t)y * (size_t)width + (size_t)x) * 3 + k] = c[k];
        }
    }
    return 0;
}
