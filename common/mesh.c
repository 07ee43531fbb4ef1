#include "mesh.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"

typedef struct {
    const char *path;
    int line;
    char *err;
    size_t err_size;
} obj_reader;

static int fail(obj_reader *r, const char *problem, const char *detail)
{
    snprintf(r->err, r->err_size, "%s:%d: %s%s", r->path, r->line, problem, detail ? detail : "");
    return -1;
}

/* Reads n finite numbers from s; the rest of the line must be empty (a
 * fourth "w" coordinate of v and vt is allowed and dropped). */
static int read_numbers(obj_reader *r, const char *s, real *out, int n, int optional_extra)
{
    char *end;
    for (int k = 0; k < n; k++) {
        errno = 0;
        double x = strtod(s, &end);
        if (end == s || errno == ERANGE || !isfinite(x) || real_abs((real)x) > REAL_MAX / 4)
            return fail(r, "missing or malformed number", NULL);
        out[k] = (real)x;
        s = end;
    }
    for (int k = 0; k < optional_extra; k++) {
        double w = strtod(s, &end);
        if (end != s && !isfinite(w))
            return fail(r, "missing or malformed number", NULL);
        s = end;
    }
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n')
        s++;
    if (*s)
        return fail(r, "unexpected text after the numbers: ", s);
    return 0;
}

/* An index of a face corner: 1-based, or negative counting back from the
 * last one read.  Returns the 0-based index or -1 after failing. */
static int resolve_index(obj_reader *r, long index, int count, const char *what)
{
    long resolved = index > 0 ? index - 1 : count + index;
    if (index == 0 || resolved < 0 || resolved >= count) {
        char detail[96];
        snprintf(detail, sizeof detail, "%s index %ld (there are %d)", what, index, count);
        fail(r, "face refers to a missing ", detail);
        return -1;
    }
    return (int)resolved;
}

/* One corner "v", "v/vt", "v//vn" or "v/vt/vn"; advances *s. */
static int read_corner(obj_reader *r, const char **s, const mesh *m, int *v, int *vt, int *vn)
{
    char *end;
    long index[3] = {0, 0, 0};
    bool given[3] = {false, false, false};
    const char *p = *s;
    for (int part = 0; part < 3; part++) {
        if (part > 0) {
            if (*p != '/')
                break;
            p++;
            if (*p == '/' || *p == ' ' || *p == '\t' || *p == '\0' || *p == '\r' || *p == '\n')
                continue; /* empty vt in v//vn */
        }
        errno = 0;
        index[part] = strtol(p, &end, 10);
        if (end == p || errno)
            return fail(r, "malformed face corner near: ", *s);
        given[part] = true;
        p = end;
    }
    static const char *const what[3] = {"vertex", "texture coordinate", "normal"};
    const int count[3] = {m->n_positions, m->n_uvs, m->n_normals};
    int *resolved[3] = {v, vt, vn};
    for (int part = 0; part < 3; part++) {
        *resolved[part] = -1;
        if (given[part] && (*resolved[part] = resolve_index(r, index[part], count[part], what[part])) < 0)
            return -1; /* the first bad index is the one named */
    }
    *s = p;
    return 0;
}

static int read_face(obj_reader *r, const char *s, mesh *m, int *cap_faces)
{
    int first[3], previous[3], corners = 0;
    for (;;) {
        while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n')
            s++;
        if (!*s)
            break;
        int c[3];
        if (read_corner(r, &s, m, &c[0], &c[1], &c[2]) != 0)
            return -1;
        if (corners == 0)
            memcpy(first, c, sizeof c);
        if (corners >= 2) { /* triangle fan: (first, previous, this) */
            if (grow((void **)&m->faces, cap_faces, m->n_faces + 1, sizeof *m->faces) != 0)
                return fail(r, "out of memory", NULL);
            mesh_face *f = &m->faces[m->n_faces++];
            const int *corner[3] = {first, previous, c};
            for (int k = 0; k < 3; k++) {
                f->v[k] = corner[k][0];
                f->vt[k] = corner[k][1];
                f->vn[k] = corner[k][2];
            }
        }
        memcpy(previous, c, sizeof c);
        corners++;
    }
    if (corners < 3)
        return fail(r, "a face needs at least 3 corners", NULL);
    return 0;
}

int mesh_load(const char *path, mesh *m, char *err, size_t err_size)
{
    *m = (mesh){0};
    obj_reader r = {path, 0, err, err_size};
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, err_size, "%s: cannot read the mesh: %s", path, strerror(errno));
        return -1;
    }
    int cap_positions = 0, cap_normals = 0, cap_uvs = 0, cap_faces = 0;
    char *line = NULL;
    size_t line_cap = 0;
    int status = 0;
    while (status == 0 && getline(&line, &line_cap, f) != -1) {
        r.line++;
        const char *s = line;
        while (*s == ' ' || *s == '\t')
            s++;
        real x[3];
        if (strncmp(s, "v ", 2) == 0 || strncmp(s, "v\t", 2) == 0) {
            status = read_numbers(&r, s + 2, x, 3, 1);
            if (status == 0 && grow((void **)&m->positions, &cap_positions, m->n_positions + 1, sizeof *m->positions))
                status = fail(&r, "out of memory", NULL);
            if (status == 0)
                m->positions[m->n_positions++] = vec3_make(x[0], x[1], x[2]);
        } else if (strncmp(s, "vn ", 3) == 0) {
            status = read_numbers(&r, s + 3, x, 3, 0);
            if (status == 0 && grow((void **)&m->normals, &cap_normals, m->n_normals + 1, sizeof *m->normals))
                status = fail(&r, "out of memory", NULL);
            if (status == 0)
                m->normals[m->n_normals++] = vec3_make(x[0], x[1], x[2]);
        } else if (strncmp(s, "vt ", 3) == 0) {
            status = read_numbers(&r, s + 3, x, 2, 1);
            if (status == 0 && grow((void **)&m->uvs, &cap_uvs, m->n_uvs + 1, sizeof *m->uvs))
                status = fail(&r, "out of memory", NULL);
            if (status == 0)
                m->uvs[m->n_uvs++] = (mesh_uv){x[0], x[1]};
        } else if (strncmp(s, "f ", 2) == 0) {
            status = read_face(&r, s + 2, m, &cap_faces);
        } else if (*s == '#' || *s == '\n' || *s == '\r' || *s == '\0' || strncmp(s, "o ", 2) == 0 ||
                   strncmp(s, "g ", 2) == 0 || strncmp(s, "s ", 2) == 0 || strncmp(s, "usemtl", 6) == 0 ||
                   strncmp(s, "mtllib", 6) == 0) {
            /* comments and grouping: nothing to model */
        } else {
            char word[32];
            snprintf(word, sizeof word, "%.*s", (int)strcspn(s, " \t\r\n"), s);
            status = fail(&r, "unknown statement: ", word);
        }
    }
    if (status == 0 && ferror(f))
        status = fail(&r, "read error", NULL);
    if (status == 0 && m->n_faces == 0) {
        r.line = 0;
        snprintf(err, err_size, "%s: the mesh has no faces", path);
        status = -1;
    }
    free(line);
    fclose(f);
    if (status == 0) {
        m->path = strdup(path);
        if (!m->path)
            status = fail(&r, "out of memory", NULL);
    }
    if (status != 0)
        mesh_free(m);
    return status;
}

void mesh_free(mesh *m)
{
    free(m->path);
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->faces);
    *m = (mesh){0};
}
