#include "input_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *kind_of(mode_t mode)
{
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISSOCK(mode))
        return "a socket";
    return "not a plain file";
}

FILE *input_file_open(const char *path, const char *what, long long max_bytes, char *err, size_t err_size)
{
    /* O_NONBLOCK: opening a FIFO must not wait for a writer. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        snprintf(err, err_size, "%s: cannot read %s: %s", path, what, strerror(errno));
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        snprintf(err, err_size, "%s: cannot read %s: %s", path, what, strerror(errno));
        close(fd);
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        snprintf(err, err_size, "%s: %s is %s, not a regular file", path, what, kind_of(st.st_mode));
        close(fd);
        return NULL;
    }
    if ((long long)st.st_size > max_bytes) {
        snprintf(err, err_size, "%s: %s is %lld bytes, more than the %lld one such file may hold", path, what,
                 (long long)st.st_size, max_bytes);
        close(fd);
        return NULL;
    }
    int flags = fcntl(fd, F_GETFL);
    FILE *f = flags == -1 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == -1 ? NULL : fdopen(fd, "rb");
    if (!f) {
        snprintf(err, err_size, "%s: cannot read %s: %s", path, what, strerror(errno));
        close(fd);
    }
    return f;
}

int input_file_read_all(const char *path, const char *what, long long max_bytes, unsigned char **bytes,
                        size_t *size, char *err, size_t err_size)
{
    *bytes = NULL;
    *size = 0;
    FILE *f = input_file_open(path, what, max_bytes, err, err_size);
    if (!f)
        return -1;
    size_t cap = 1 << 16, n = 0;
    unsigned char *buffer = malloc(cap);
    int status = buffer ? 0 : -1;
    if (!buffer)
        snprintf(err, err_size, "%s: out of memory", path);
    while (status == 0) {
        if (n == cap) {
            unsigned char *bigger = realloc(buffer, cap * 2);
            if (!bigger) {
                snprintf(err, err_size, "%s: out of memory", path);
                status = -1;
                break;
            }
            buffer = bigger;
            cap *= 2;
        }
        size_t got = fread(buffer + n, 1, cap - n, f);
        n += got;
        if ((long long)n > max_bytes) {
            snprintf(err, err_size, "%s: %s holds more than the %lld bytes one such file may hold", path, what,
                     max_bytes);
            status = -1;
        } else if (got == 0) {
            if (ferror(f)) {
                snprintf(err, err_size, "%s: read error: %s", path, strerror(errno));
                status = -1;
            }
            break;
        }
    }
    fclose(f);
    if (status != 0) {
        free(buffer);
        return -1;
    }
    *bytes = buffer;
    *size = n;
    return 0;
}
