/* output_file.h - a file written whole or not at all.
 *
 * The data go to a temporary file in the destination's folder, which is
 * renamed over the destination only when it is complete: a failure never
 * leaves a truncated file and never clobbers an existing one.  The
 * destination must be a new path or a regular file (png_check_output).
 */
#ifndef RT_OUTPUT_FILE_H
#define RT_OUTPUT_FILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    FILE *file;       /* write here */
    const char *path; /* the destination */
    char *tmp;        /* the temporary file's name */
} output_file;

/* Opens the temporary file for `path`.  Returns 0, or -1 with "path:
 * problem" in err. */
int output_open(output_file *f, const char *path, char *err, size_t err_size);

/* Flushes, closes and renames the file over its destination; `what` names
 * the content in a message ("the PNG").  On any failure (also a write error
 * seen earlier, or `failed`) the temporary file is removed.  Returns 0, or
 * -1 with "path: problem" in err. */
int output_close(output_file *f, int failed, const char *what, char *err, size_t err_size);

#endif
