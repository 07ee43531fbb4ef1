/* mesh.h - triangle meshes from Wavefront .obj files.
 *
 * Only what the scene format needs: positions (v), texture coordinates (vt),
 * normals (vn) and faces (f).  Polygons are split into triangle fans.  Other
 * statements (o, g, s, usemtl, mtllib) are accepted and ignored.
 */
#ifndef RT_MESH_H
#define RT_MESH_H

#include <stddef.h>

#include "vec3.h"

typedef struct {
    int v[3];  /* indices into positions */
    int vt[3]; /* indices into uvs, or -1 */
    int vn[3]; /* indices into normals, or -1 */
} mesh_face;

typedef struct {
    real u, v;
} mesh_uv;

typedef struct {
    char *path;
    vec3 *positions;
    int n_positions;
    vec3 *normals;
    int n_normals;
    mesh_uv *uvs;
    int n_uvs;
    mesh_face *faces;
    int n_faces;
} mesh;

/* Returns 0, or -1 with "path:line: problem" in err (nothing to free). */
int mesh_load(const char *path, mesh *m, char *err, size_t err_size);
void mesh_free(mesh *m);

#endif
