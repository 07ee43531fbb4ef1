/* Hostile submission for chapter 05 (tools/hostile.sh): writes a function's
 * bytes (a correct lambert of its own, copied from its code) into memory that
 * runs, with no file of its own and no write to /proc/self/mem: /dev/zero
 * mapped shared and executable (a file, so the seal's test of anonymous or
 * writable memory lets it pass), a second mapping of the same pages made by
 * mremap with an old size of 0, made writable (mprotect without PROT_EXEC),
 * then the bytes written through the second and run through the first: the
 * way the hand-out's compiled reference, as bytes, would run.  The seal must
 * refuse the shared executable mapping: lambert returns zeros (0 points); it
 * says when the code ran. */
#define _GNU_SOURCE
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

__attribute__((noinline)) static color formula(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    vec3 to_light = vec3_sub(light->position, point);
    real r2 = vec3_dot(to_light, to_light);
    real n_dot = vec3_dot(n, to_light);
    if (!(n_dot > 0))
        return color_make(0, 0, 0);
    real falloff = n_dot / (r2 * real_sqrt(r2));
    return color_make(k_d.r * light->intensity.r * falloff, k_d.g * light->intensity.g * falloff,
                      k_d.b * light->intensity.b * falloff);
}

typedef color (*lambert_fn)(color, vec3, vec3, const scene_light *);

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    static lambert_fn found;
    static int tried;
    if (!tried) {
        tried = 1;
        int fd = open("/dev/zero", O_RDWR);
        void *code = fd < 0 ? MAP_FAILED : mmap(NULL, 4096, PROT_READ | PROT_EXEC, MAP_SHARED, fd, 0);
        void *alias = code == MAP_FAILED ? MAP_FAILED : mremap(code, 0, 4096, MREMAP_MAYMOVE);
        if (fd >= 0)
            close(fd);
        if (alias != MAP_FAILED && mprotect(alias, 4096, PROT_READ | PROT_WRITE) == 0) {
            memcpy(alias, (const void *)formula, 4096); /* its bytes and what follows */
            fprintf(stderr, "devzero_exec: code written through a writable alias of executable memory ran\n");
            found = (lambert_fn)code;
        }
    }
    return found ? found(k_d, point, n, light) : color_make(0, 0, 0);
}
