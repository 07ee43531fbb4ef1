/* icosahedron.c - chapter 03: the regular icosahedron. */
#include "03_triangle/scenes/icosahedron.h"

const int icosahedron_faces[ICOSAHEDRON_FACES][3] = {
    {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, /* around vertex 0 */
    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   /* the band below them */
    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},   /* around vertex 3 */
    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1},   /* the band above them */
};

void icosahedron_vertices(vec3 centre, real radius, vec3 out[ICOSAHEDRON_VERTICES])
{
    const real phi = (1 + real_sqrt(5)) / 2; /* the golden ratio */
    const vec3 corners[ICOSAHEDRON_VERTICES] = {
        {-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, /* in the plane z = 0 */
        {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi}, /* in x = 0 */
        {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}, /* in y = 0 */
    };
    for (int k = 0; k < ICOSAHEDRON_VERTICES; k++)
        out[k] = vec3_add(centre, vec3_scale(vec3_normalize(corners[k]), radius));
}

void icosahedron_triangles(const vec3 vertices[ICOSAHEDRON_VERTICES], triangle out[ICOSAHEDRON_FACES])
{
    for (int f = 0; f < ICOSAHEDRON_FACES; f++) {
        const int *v = icosahedron_faces[f];
        out[f] = (triangle){vertices[v[0]], vertices[v[1]], vertices[v[2]]};
    }
}

void icosahedron_edges(int out[ICOSAHEDRON_EDGES][2])
{
    /* In a closed mesh wound consistently, each edge occurs in one face as
     * i -> j and in the other as j -> i: keep the occurrence with i < j. */
    int n = 0;
    for (int f = 0; f < ICOSAHEDRON_FACES; f++)
        for (int k = 0; k < 3; k++) {
            int i = icosahedron_faces[f][k], j = icosahedron_faces[f][(k + 1) % 3];
            if (i < j && n < ICOSAHEDRON_EDGES) {
                out[n][0] = i;
                out[n][1] = j;
                n++;
            }
        }
}
