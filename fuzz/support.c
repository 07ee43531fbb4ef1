#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fuzz.h"

const char *fuzz_input_name = "(the input libFuzzer saves)";

void fuzz_check(bool ok, const char *format, ...)
{
    if (ok)
        return;
    fprintf(stderr, "contract broken: ");
    va_list args;
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fprintf(stderr, "\ninput: %s\n", fuzz_input_name);
    abort();
}

static char folder[64];

static void remove_folder(void)
{
    static const char *const names[] = {"m.obj", "t.png", "scene.xml", "mesh.obj"};
    char path[128];
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        snprintf(path, sizeof path, "%s/%s", folder, names[k]);
        unlink(path);
    }
    rmdir(folder);
}

/* A 2 x 2 RGB PNG. */
static const uint8_t t_png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00,
    0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x02, 0x00, 0x00, 0x00, 0xfd, 0xd4, 0x9a, 0x73, 0x00,
    0x00, 0x00, 0x12, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0xc0, 0x00, 0xc2, 0x0c,
    0xff, 0x81, 0x00, 0x00, 0x1f, 0xee, 0x05, 0xfb, 0x0b, 0xd9, 0x68, 0x8b, 0x00, 0x00, 0x00, 0x00, 0x49,
    0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
static const char m_obj[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                            "f 1/1/1 2/2/1 3/3/1 4/4/1\n";

const char *fuzz_folder(void)
{
    if (folder[0])
        return folder;
    const char *base = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    snprintf(folder, sizeof folder, "%s/rt-fuzz-XXXXXX", base);
    if (!mkdtemp(folder)) {
        perror(folder);
        abort();
    }
    atexit(remove_folder);
    fuzz_write("t.png", t_png, sizeof t_png);
    fuzz_write("m.obj", (const uint8_t *)m_obj, strlen(m_obj));
    return folder;
}

const char *fuzz_write(const char *name, const uint8_t *data, size_t size)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s", fuzz_folder(), name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0) {
        perror(path);
        abort();
    }
    return path;
}

bool fuzz_names_line(const char *err, const char *path, long max_line)
{
    size_t n = strlen(path);
    if (strncmp(err, path, n) != 0 || err[n] != ':')
        return false;
    char *end;
    long line = strtol(err + n + 1, &end, 10);
    return end != err + n + 1 && end[0] == ':' && end[1] == ' ' && line >= 1 && line <= max_line;
}

long fuzz_count_lines(const uint8_t *data, size_t size, bool cr_ends_lines)
{
    long lines = 0;
    for (size_t k = 0; k < size; k++)
        lines += data[k] == '\n' || (cr_ends_lines && data[k] == '\r' && (k + 1 == size || data[k + 1] != '\n'));
    return lines + (size > 0 && data[size - 1] != '\n');
}
