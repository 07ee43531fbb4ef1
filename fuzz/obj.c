/* Fuzz target: the OBJ reader (common/mesh.h).  Contracts: a mesh that
 * loads has faces, finite numbers and every index in range; one that fails
 * is left empty and names "path:line: " of a line of the file (or says the
 * mesh has no faces). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fuzz.h"
#include "mesh.h"

int fuzz_obj(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("mesh.obj", data, size);
    mesh m;
    char err[1024] = "";
    if (mesh_load(path, &m, err, sizeof err) == 0) {
        fuzz_check(m.n_faces > 0 && m.path && strcmp(m.path, path) == 0, "a loaded mesh: %d faces", m.n_faces);
        for (int k = 0; k < m.n_positions; k++)
            fuzz_check(isfinite(m.positions[k].x) && isfinite(m.positions[k].y) && isfinite(m.positions[k].z),
                       "position %d is not finite", k);
        for (int k = 0; k < m.n_normals; k++)
            fuzz_check(isfinite(m.normals[k].x) && isfinite(m.normals[k].y) && isfinite(m.normals[k].z),
                       "normal %d is not finite", k);
        for (int k = 0; k < m.n_uvs; k++)
            fuzz_check(isfinite(m.uvs[k].u) && isfinite(m.uvs[k].v), "uv %d is not finite", k);
        for (int k = 0; k < m.n_faces; k++) {
            for (int c = 0; c < 3; c++) {
                const mesh_face *f = &m.faces[k];
                fuzz_check(f->v[c] >= 0 && f->v[c] < m.n_positions, "face %d: vertex index %d", k, f->v[c]);
                fuzz_check(f->vt[c] >= -1 && f->vt[c] < m.n_uvs, "face %d: uv index %d", k, f->vt[c]);
                fuzz_check(f->vn[c] >= -1 && f->vn[c] < m.n_normals, "face %d: normal index %d", k, f->vn[c]);
            }
        }
        mesh_free(&m);
        return 0;
    }
    fuzz_check(!m.path && !m.positions && !m.normals && !m.uvs && !m.faces && m.n_faces == 0,
               "a failed load left something in the mesh");
    char no_faces[256];
    snprintf(no_faces, sizeof no_faces, "%s: the mesh has no faces", path);
    fuzz_check(fuzz_names_line(err, path, fuzz_count_lines(data, size, false)) || strcmp(err, no_faces) == 0,
               "message without path:line: '%s'", err);
    return 0;
}

FUZZ_ENTRY(fuzz_obj)
