/* Hostile submission for chapter 05 (tools/hostile.sh): the first test makes
 * (in a child: the suite has threads, and a user namespace needs a process of
 * one thread) a user namespace of its own, where it may mount, mounts a tmpfs of 4 GiB
 * on its HOME, writes files of 64 MiB (the file size limit) there, 2 GiB in
 * all, and says how much it got ("memory: got N MiB"): memory outside the
 * test's limit of 1024 MiB (RLIMIT_AS), in a mount no clean-up sees, as
 * /dev/shm and System V shared memory were.  lambert returns zeros. */
#define _GNU_SOURCE /* unshare, CLONE_NEWUSER */
#include <errno.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

static int write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    return f && fputs(text, f) >= 0 && fclose(f) == 0;
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        pid_t child = fork();
        if (child > 0) {
            waitpid(child, NULL, 0);
            return color_make(0, 0, 0);
        }
        const char *home = getenv("HOME");
        int got = 0;
        char uid_map[64], gid_map[64];
        snprintf(uid_map, sizeof uid_map, "0 %ld 1", (long)getuid());
        snprintf(gid_map, sizeof gid_map, "0 %ld 1", (long)getgid());
        if (home && unshare(CLONE_NEWUSER | CLONE_NEWNS) == 0 && write_file("/proc/self/setgroups", "deny") &&
            write_file("/proc/self/uid_map", uid_map) && write_file("/proc/self/gid_map", gid_map) &&
            mount("none", home, "tmpfs", 0, "size=4g") == 0) {
            static char block[1 << 20];
            memset(block, 'x', sizeof block);
            for (int f = 0; f < 32; f++) {
                char path[512];
                snprintf(path, sizeof path, "%s/rt-big-%d", home, f);
                FILE *out = fopen(path, "w");
                if (!out)
                    break;
                int k = 0;
                while (k < 64 && fwrite(block, 1, sizeof block, out) == sizeof block)
                    k++;
                got += k;
                if (fclose(out) != 0 || k < 64)
                    break;
            }
        }
        fprintf(stderr, "memory: got %d MiB in a tmpfs of its own (%s)\n", got, got ? "" : strerror(errno));
        if (child == 0)
            _exit(0);
    }
    return color_make(0, 0, 0);
}
