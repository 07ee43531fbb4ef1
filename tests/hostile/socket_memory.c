/* Hostile submission for chapter 05 (tools/hostile.sh): the first call
 * raises its limit on descriptors as far as it may, then fills pairs of
 * local sockets (AF_UNIX, which the seal allows) until 2 GiB wait in their
 * buffers: memory of the kernel's, outside the test's limit of 1024 MiB on
 * its address space, up to some 200 KiB a pair.  It says how much it got
 * ("memory: got N MiB").  lambert returns zeros. */
#define _DEFAULT_SOURCE /* socketpair's flags */
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        struct rlimit files;
        if (getrlimit(RLIMIT_NOFILE, &files) == 0) {
            files.rlim_cur = files.rlim_max;
            setrlimit(RLIMIT_NOFILE, &files);
        }
        static char block[1 << 16];
        memset(block, 'x', sizeof block);
        long long got = 0;
        int pair[2];
        while (got < (2LL << 30) && socketpair(AF_UNIX, SOCK_STREAM, 0, pair) == 0) {
            fcntl(pair[0], F_SETFL, O_NONBLOCK);
            ssize_t n;
            while ((n = write(pair[0], block, sizeof block)) > 0)
                got += n;
        }
        fprintf(stderr, "memory: got %lld MiB in socket buffers\n", got >> 20);
    }
    return color_make(0, 0, 0);
}
