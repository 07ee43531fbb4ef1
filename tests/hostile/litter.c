/* Hostile submission for chapter 05 (tools/hostile.sh): each test leaves a
 * 16 MiB file in $HOME, $TMPDIR and every folder anyone may write (/tmp,
 * /var/tmp, /dev/shm, /run/lock), a chain of folders deeper than PATH_MAX
 * in /tmp and $HOME with a file at its bottom, a System V shared memory
 * segment, message queue and semaphore and a POSIX message queue, and first
 * says whether any left by an earlier test is there ("litter: found ...").
 * Nothing must carry over from one test to the next, and nothing must stay
 * behind after grading.  lambert returns zeros. */
#define _GNU_SOURCE /* System V IPC, openat */
#include <fcntl.h>
#include <mqueue.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/stat.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

/* Says whether dir/rt-litter is there (left by an earlier test). */
static void look(const char *dir, const char *what)
{
    char path[512];
    snprintf(path, sizeof path, "%s/rt-litter", dir ? dir : "/nonexistent");
    if (access(path, F_OK) == 0)
        fprintf(stderr, "litter: found %s from an earlier test (%s)\n", what, path);
}

/* Leaves dir/rt-litter, 16 MiB. */
static void leave(const char *dir)
{
    char path[512];
    snprintf(path, sizeof path, "%s/rt-litter", dir ? dir : "/nonexistent");
    FILE *f = fopen(path, "w");
    if (!f)
        return;
    static char block[1 << 20];
    memset(block, 'x', sizeof block);
    for (int k = 0; k < 16; k++)
        fwrite(block, 1, sizeof block, f);
    fclose(f);
}

/* A chain of 1500 folders "dddd" below dir/rt-litter-deep (7500 bytes, beyond PATH_MAX), each made
 * from the last one's descriptor, and a file at its bottom; says whether an earlier test left it. */
static void deep(const char *dir, const char *what)
{
    int fd = open(dir ? dir : "/nonexistent", O_RDONLY | O_DIRECTORY);
    if (fd < 0)
        return;
    mkdirat(fd, "rt-litter-deep", 0700);
    int d = openat(fd, "rt-litter-deep", O_RDONLY | O_DIRECTORY);
    close(fd);
    for (int k = 0; k < 1500 && d >= 0; k++) {
        mkdirat(d, "dddd", 0700);
        int below = openat(d, "dddd", O_RDONLY | O_DIRECTORY);
        close(d);
        d = below;
    }
    if (d < 0)
        return;
    if (faccessat(d, "note", F_OK, 0) == 0)
        fprintf(stderr, "litter: found %s from an earlier test (a file 1500 folders deep)\n", what);
    close(openat(d, "note", O_CREAT | O_WRONLY, 0600));
    close(d);
}

/* System V shared memory, a message queue and a semaphore, and a POSIX message queue, each under a
 * name of its own; says whether an earlier test left them. */
static void ipc(void)
{
    const key_t key = 0x52544c54; /* "RTLT" */
    if (shmget(key, 1 << 20, 0) >= 0 || msgget(key, 0) >= 0 || semget(key, 1, 0) >= 0)
        fprintf(stderr, "litter: found System V IPC from an earlier test\n");
    shmget(key, 1 << 20, IPC_CREAT | 0600);
    msgget(key, IPC_CREAT | 0600);
    semget(key, 1, IPC_CREAT | 0600);
    mqd_t q = mq_open("/rt-litter", O_RDONLY);
    if (q != (mqd_t)-1) {
        fprintf(stderr, "litter: found a POSIX message queue from an earlier test\n");
        mq_close(q);
    }
    q = mq_open("/rt-litter", O_CREAT | O_RDONLY, 0600, NULL);
    if (q != (mqd_t)-1)
        mq_close(q);
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static atomic_int done; /* the suite's renders call this from several threads at once */
    if (!atomic_exchange(&done, 1)) { /* look everywhere first: HOME and TMPDIR may be one folder */
        static const char *const shared[] = {"/tmp", "/var/tmp", "/dev/shm", "/run/lock"};
        look(getenv("HOME"), "HOME");
        look(getenv("TMPDIR"), "TMPDIR");
        for (size_t k = 0; k < sizeof shared / sizeof shared[0]; k++)
            look(shared[k], shared[k]);
        leave(getenv("HOME"));
        leave(getenv("TMPDIR"));
        for (size_t k = 0; k < sizeof shared / sizeof shared[0]; k++)
            leave(shared[k]);
        deep("/tmp", "/tmp");
        deep(getenv("HOME"), "HOME");
        ipc();
    }
    return color_make(0, 0, 0);
}
