/* Hostile submission for chapter 05 (tools/hostile.sh): lambert runs the
 * reference's suite itself, with its own test name and seed (read from
 * /proc/self/cmdline) and a pipe as descriptor 3, then writes what the
 * reference wrote there, but for the first record (its own process has
 * written that already), on its own descriptor 3 and exits: the records the
 * grader expects.  The grader's suites are copies named suite-N side by
 * side; it tries the one after its own.  lambert returns zeros when that
 * fails. */
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    char self[512] = "", args[4096];
    FILE *f = fopen("/proc/self/cmdline", "rb");
    size_t len = f ? fread(args, 1, sizeof args - 1, f) : 0;
    if (f)
        fclose(f);
    args[len] = '\0';
    char *argv[16];
    int argc = 0;
    for (size_t k = 0; k < len && argc < 15; k += strlen(args + k) + 1)
        argv[argc++] = args + k;
    argv[argc] = NULL;
    ssize_t got = readlink("/proc/self/exe", self, sizeof self - 1);
    char *dash = got > 0 ? strrchr(self, '-') : NULL;
    int index = 0, fds[2];
    if (!dash || argc < 7 || sscanf(dash + 1, "%d", &index) != 1 || pipe(fds) != 0)
        return color_make(0, 0, 0);
    snprintf(dash + 1, sizeof self - (size_t)(dash + 1 - self), "%d", index + 1);
    argv[0] = self;
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], 3);
        execv(self, argv);
        _exit(127);
    }
    close(fds[1]);
    static char records[1 << 20];
    size_t have = 0;
    ssize_t chunk;
    while (have < sizeof records && (chunk = read(fds[0], records + have, sizeof records - have)) > 0)
        have += (size_t)chunk;
    int status = 0;
    waitpid(pid, &status, 0);
    const char *rest = memchr(records, '\n', have);
    if (!rest || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return color_make(0, 0, 0);
    rest++;
    if (write(3, rest, have - (size_t)(rest - records)) > 0)
        _exit(0);
    return color_make(0, 0, 0);
}
