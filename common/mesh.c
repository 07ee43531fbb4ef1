#include "mesh.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "input_file.h"

typedef struct {
    const char *path;
    long line; /* at most MESH_MAX_FILE_BYTES lines */
    long long bytes; /* read so far, at most MESH_MAX_FILE_BYTES */
    char *err;
    size_t err_size;
} obj_reader;

static int fail(obj_reader *r, const char *problem, const char *detail)
{
    snprintf(r->err, r->err_size, "%s:%ld: %s%s", r->path, r->line, problem, detail ? detail : "");
    return -1;
}

static int failf(obj_reader *r, const char *format, long long limit, const char *what)
{
    char problem[160];
    snprintf(problem, sizeof problem, format, limit, what);
    return fail(r, problem, NULL);
}

/* Room for one more of `what` (one of the MESH_MAX_ITEMS kinds). */
static int make_room(obj_reader *r, void **array, int *capacity, int count, size_t size, const char *what)
{
    if (count >= MESH_MAX_ITEMS)
        return failf(r, "more than %lld %s (the limit of one mesh)", MESH_MAX_ITEMS, what);
    if (grow(array, capacity, count + 1, size) != 0)
        return fail(r, "out of memory", NULL);
    return 0;
}

/* Reads the next line into buf (MESH_MAX_LINE_BYTES + 1 bytes), without its
 * newline.  Returns 1 for a line, 0 at the end of the file, -1 after failing. */
static int read_line(obj_reader *r, FILE *f, char *buf)
{
    size_t n = 0;
    int c;
    r->line++;
    while ((c = getc(f)) != EOF) {
        if (++r->bytes > MESH_MAX_FILE_BYTES)
            return failf(r, "the file holds more than %lld bytes (the limit of one %s)", MESH_MAX_FILE_BYTES,
                         "mesh file");
        if (c == '\n')
            break;
        if (c == '\0')
            return fail(r, "the line holds a NUL byte: this is not a text file", NULL);
        if (n == MESH_MAX_LINE_BYTES)
            return failf(r, "the line is longer than %lld bytes (the limit of one %s)", MESH_MAX_LINE_BYTES, "line");
        buf[n++] = (char)c;
    }
    buf[n] = '\0';
    if (c == EOF && n == 0) {
        r->line--; /* no line there */
        return 0;
    }
    return 1;
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
        if (corners == MESH_MAX_CORNERS)
            return failf(r, "a face has more than %lld corners (the limit of one %s)", MESH_MAX_CORNERS, "face");
        if (corners >= 2) { /* triangle fan: (first, previous, this) */
            if (make_room(r, (void **)&m->faces, cap_faces, m->n_faces, sizeof *m->faces, "triangles") != 0)
                return -1;
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

/* Whether the statement's keyword, its first `length` characters of s, is `word`. */
static int keyword_is(const char *s, size_t length, const char *word)
{
    return strlen(word) == length && strncmp(s, word, length) == 0;
}

int mesh_load(const char *path, mesh *m, char *err, size_t err_size)
{
    *m = (mesh){0};
    obj_reader r = {path, 0, 0, err, err_size};
    FILE *f = input_file_open(path, "the mesh", MESH_MAX_FILE_BYTES, err, err_size);
    if (!f)
        return -1;
    int cap_positions = 0, cap_normals = 0, cap_uvs = 0, cap_faces = 0;
    char *line = malloc(MESH_MAX_LINE_BYTES + 1);
    int status = line ? 0 : fail(&r, "out of memory", NULL);
    int more;
    while (status == 0 && (more = read_line(&r, f, line)) != 0) {
        if (more < 0) {
            status = -1;
            break;
        }
        const char *s = line;
        if (r.line == 1 && strncmp(s, "\xef\xbb\xbf", 3) == 0)
            s += 3; /* a UTF-8 byte order mark, as some editors write one */
        while (*s == ' ' || *s == '\t')
            s++;
        /* the statement's keyword, and what follows it */
        const size_t length = strcspn(s, " \t\r");
        const char *rest = s + length;
        real x[3];
        if (keyword_is(s, length, "v")) {
            status = read_numbers(&r, rest, x, 3, 1);
            if (status == 0)
                status = make_room(&r, (void **)&m->positions, &cap_positions, m->n_positions, sizeof *m->positions,
                                   "vertex positions");
            if (status == 0)
                m->positions[m->n_positions++] = vec3_make(x[0], x[1], x[2]);
        } else if (keyword_is(s, length, "vn")) {
            status = read_numbers(&r, rest, x, 3, 0);
            if (status == 0)
                status = make_room(&r, (void **)&m->normals, &cap_normals, m->n_normals, sizeof *m->normals,
                                   "normals");
            if (status == 0)
                m->normals[m->n_normals++] = vec3_make(x[0], x[1], x[2]);
        } else if (keyword_is(s, length, "vt")) {
            status = read_numbers(&r, rest, x, 2, 1);
            if (status == 0)
                status = make_room(&r, (void **)&m->uvs, &cap_uvs, m->n_uvs, sizeof *m->uvs,
                                   "texture coordinates");
            if (status == 0)
                m->uvs[m->n_uvs++] = (mesh_uv){x[0], x[1]};
        } else if (keyword_is(s, length, "f")) {
            status = read_face(&r, rest, m, &cap_faces);
        } else if (*s == '#' || length == 0 || keyword_is(s, length, "o") || keyword_is(s, length, "g") ||
                   keyword_is(s, length, "s") || keyword_is(s, length, "usemtl") || keyword_is(s, length, "mtllib") ||
                   keyword_is(s, length, "l") || keyword_is(s, length, "p")) {
            /* comments, grouping, materials, and lines and points (no area for a ray to hit): nothing to model */
        } else {
            char word[32];
            snprintf(word, sizeof word, "%.*s", (int)(length < 31 ? length : 31), s);
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
