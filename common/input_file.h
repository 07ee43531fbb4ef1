/* input_file.h - opening a file the renderer reads, and nothing else.
 *
 * A scene, mesh or texture path may name anything: a directory, a FIFO that
 * blocks until someone writes to it, /dev/zero that never ends.  Each is
 * refused at once with the reason, before a byte is read.  A regular file is
 * refused when it is larger than what one such file may hold; the readers
 * also count what they read against the same limit, because some regular
 * files (in /proc, say) report a size of 0 and hold more.
 */
#ifndef RT_INPUT_FILE_H
#define RT_INPUT_FILE_H

#include <stddef.h>
#include <stdio.h>

/* Opens `path` for reading when it is a regular file of at most max_bytes.
 * Otherwise returns NULL with "path: problem" in err, the problem naming
 * `what` ("the mesh"): "cannot read the mesh: No such file or directory",
 * "the mesh is a directory, not a regular file", "the mesh is 300000000
 * bytes, more than the 268435456 one mesh file may hold". */
FILE *input_file_open(const char *path, const char *what, long long max_bytes, char *err, size_t err_size);

/* The whole file, read as input_file_open() allows it: *bytes (malloc'ed,
 * free it) and *size.  Returns 0, or -1 with "path: problem" in err. */
int input_file_read_all(const char *path, const char *what, long long max_bytes, unsigned char **bytes,
                        size_t *size, char *err, size_t err_size);

#endif
