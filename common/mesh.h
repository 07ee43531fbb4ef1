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

/* What one mesh may hold; beyond these the file is refused with a message
 * naming the limit.  They bound the memory one file can ask for (about
 * 1.6 GB at most) and keep every count and line number far from INT_MAX. */
#define MESH_MAX_FILE_BYTES (256LL << 20) /* one .obj file */
#define MESH_MAX_LINE_BYTES 65536         /* one line, without its newline */
#define MESH_MAX_CORNERS 1024             /* one face (a polygon, split into corners - 2 triangles) */
#define MESH_MAX_ITEMS (1 << 24)          /* each of: positions, texture coordinates, normals, triangles */

/* Returns 0, or -1 with "path:line: problem" in err (nothing to free).
 * A path that is not a regular file (a directory, a FIFO, /dev/zero) is
 * refused before anything is read. */
int mesh_load(const char *path, mesh *m, char *err, size_t err_size);
void mesh_free(mesh *m);

#endif
