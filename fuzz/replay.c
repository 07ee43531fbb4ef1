/* replay TARGET FILE... - feeds each FILE once to fuzz target TARGET (scene,
 * obj, options or texture), without libFuzzer: to reproduce a finding in any
 * build (gcc, gdb, the sanitizer build), or to measure the line coverage a
 * corpus reaches (docs/fuzzing.md).  Exit status 0 when every contract held;
 * a broken one aborts, naming the file. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

int main(int argc, char **argv)
{
    static const struct {
        const char *name;
        int (*target)(const uint8_t *, size_t);
    } targets[] = {{"scene", fuzz_scene}, {"obj", fuzz_obj}, {"options", fuzz_options}, {"texture", fuzz_texture}};
    int chosen = -1;
    for (int k = 0; k < 4 && argc > 1; k++)
        if (strcmp(argv[1], targets[k].name) == 0)
            chosen = k;
    if (chosen < 0) {
        fprintf(stderr, "usage: %s scene|obj|options|texture FILE...\n", argv[0]);
        return 2;
    }
    enum { MAX_INPUT = 1 << 20 };
    uint8_t *data = malloc(MAX_INPUT);
    if (!data)
        return 1;
    for (int k = 2; k < argc; k++) {
        FILE *f = fopen(argv[k], "rb");
        if (!f) {
            perror(argv[k]);
            free(data);
            return 1;
        }
        size_t size = fread(data, 1, MAX_INPUT, f);
        fclose(f);
        fuzz_input_name = argv[k];
        targets[chosen].target(data, size);
    }
    free(data);
    printf("%s: %d inputs, every contract held\n", targets[chosen].name, argc - 2);
    return 0;
}
