#include "output_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "png_write.h"

int output_open(output_file *f, const char *path, char *err, size_t err_size)
{
    *f = (output_file){.path = path};
    if (png_check_output(path, err, err_size) != 0)
        return -1;
    size_t tmp_size = strlen(path) + sizeof ".tmp-XXXXXX";
    f->tmp = malloc(tmp_size);
    if (!f->tmp) {
        snprintf(err, err_size, "%s: out of memory", path);
        return -1;
    }
    snprintf(f->tmp, tmp_size, "%s.tmp-XXXXXX", path);
    int fd = mkstemp(f->tmp);
    if (fd < 0) {
        snprintf(err, err_size, "%s: cannot create a file there: %s", path, strerror(errno));
        free(f->tmp);
        return -1;
    }
    f->file = fdopen(fd, "wb");
    if (!f->file) {
        snprintf(err, err_size, "%s: %s", path, strerror(errno));
        close(fd);
        unlink(f->tmp);
        free(f->tmp);
        return -1;
    }
    return 0;
}

int output_close(output_file *f, int failed, const char *what, char *err, size_t err_size)
{
    int status = -1;
    errno = 0;
    int written = !ferror(f->file);
    int flushed = fflush(f->file) == 0 && fsync(fileno(f->file)) == 0;
    int closed = fclose(f->file) == 0;
    if (failed || !written || !flushed || !closed) {
        snprintf(err, err_size, "%s: writing %s failed: %s", f->path, what, errno ? strerror(errno) : "encoder error");
        unlink(f->tmp);
    } else if (chmod(f->tmp, 0644), rename(f->tmp, f->path) != 0) { /* mkstemp made it 0600: make it readable */
        snprintf(err, err_size, "%s: %s", f->path, strerror(errno));
        unlink(f->tmp);
    } else {
        status = 0;
    }
    free(f->tmp);
    return status;
}
