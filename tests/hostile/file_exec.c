/* Hostile submission for chapter 05 (tools/hostile.sh): writes a function's
 * bytes (a correct lambert of its own, copied from its code) into a file of
 * each folder it may write to (its own, /tmp, /var/tmp, /dev/shm, /run/lock),
 * maps each file executable (mmap of a file with PROT_EXEC, which the seal
 * allows: the loader maps the libraries so) and calls it from there: the way
 * the hand-out's compiled reference, as bytes, would run.  Every folder the
 * test may write to must be mounted noexec: each mmap fails, and lambert
 * returns zeros (0 points); it says which folders let the file run. */
#define _DEFAULT_SOURCE
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
        const char *const folders[] = {".", "/tmp", "/var/tmp", "/dev/shm", "/run/lock"};
        for (size_t k = 0; k < sizeof folders / sizeof folders[0]; k++) {
            char path[128];
            snprintf(path, sizeof path, "%s/code-%d", folders[k], (int)getpid());
            int fd = open(path, O_RDWR | O_CREAT | O_TRUNC, 0700);
            if (fd < 0 || write(fd, (const void *)formula, 4096) != 4096) /* its bytes and what follows */
                continue;
            void *code = mmap(NULL, 4096, PROT_READ | PROT_EXEC, MAP_PRIVATE, fd, 0);
            close(fd);
            if (code == MAP_FAILED)
                continue;
            fprintf(stderr, "file_exec: code in a file of %s ran\n", folders[k]);
            found = (lambert_fn)code;
        }
    }
    return found ? found(k_d, point, n, light) : color_make(0, 0, 0);
}
