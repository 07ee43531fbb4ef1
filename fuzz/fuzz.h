/* fuzz.h - what the fuzz targets share.
 *
 * Each target is a function `int fuzz_NAME(const uint8_t *data, size_t
 * size)` that feeds one input to a reader and checks the contracts its header
 * promises.  `make fuzz` links each with libFuzzer (RT_LIBFUZZER defined:
 * FUZZ_ENTRY makes it LLVMFuzzerTestOneInput); tests/test_fuzz_corpus.c
 * links them all and replays the corpus in fuzz/corpus/ in every test build.
 * A broken contract prints what broke and aborts, which libFuzzer reports as
 * a crash and saves, and which fails the replay.
 */
#ifndef RT_FUZZ_H
#define RT_FUZZ_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

int fuzz_scene(const uint8_t *data, size_t size);
int fuzz_obj(const uint8_t *data, size_t size);
int fuzz_options(const uint8_t *data, size_t size);
int fuzz_texture(const uint8_t *data, size_t size);

#ifdef RT_LIBFUZZER
#define FUZZ_ENTRY(target)                                                                                         \
    int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);                                                 \
    int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return target(data, size); }
#else
#define FUZZ_ENTRY(target)
#endif

/* The input being replayed, named in a failure message (set by the replay). */
extern const char *fuzz_input_name;

/* When !ok: prints "contract broken: <format...>" and the input's name, and aborts. */
void fuzz_check(bool ok, const char *format, ...);

/* A folder of this process's own (removed at exit) holding m.obj (a quad
 * with texture coordinates and normals) and t.png (2 x 2 texels), which
 * fuzzed scenes may name. */
const char *fuzz_folder(void);

/* Writes data to fuzz_folder()/name and returns the path (a static buffer). */
const char *fuzz_write(const char *name, const uint8_t *data, size_t size);

/* Whether err starts with "path:N: " with 1 <= N <= max_line. */
bool fuzz_names_line(const char *err, const char *path, long max_line);

/* The number of lines of data (a last line without newline counts); XML
 * also ends a line at a CR not followed by LF. */
long fuzz_count_lines(const uint8_t *data, size_t size, bool cr_ends_lines);

#endif
