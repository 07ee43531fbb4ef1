/* scratch.c - the grader's scratch folders, and what the tests leave behind (scratch.h). */
#define _GNU_SOURCE /* nftw, unshare, O_PATH */
#include "scratch.h"

#include <fcntl.h>
#include <ftw.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ipc.h>
#include <sys/mount.h>
#include <sys/msg.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/* Runs a system tool (argv[0] a full path) with its output discarded; 0 when it succeeded. */
static int run_quietly(char *const argv[])
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        int fd = open("/dev/null", O_WRONLY);
        if (fd >= 0) {
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
        }
        execv(argv[0], argv);
        _exit(127);
    }
    int status = 1;
    if (pid < 0 || waitpid(pid, &status, 0) != pid)
        return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

static int remove_entry(const char *path, const struct stat *st, int type, struct FTW *ftw)
{
    (void)st, (void)type, (void)ftw;
    remove(path);
    return 0;
}

/* nftw stops at a path longer than PATH_MAX (a test can make folders that deep, each name relative to the
 * last): what it leaves, rm removes, whose walk has no such limit (GNU rm, like find, works from open
 * folders).  Neither follows a link or leaves the file system. */
int scratch_remove(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return 0;
    nftw(path, remove_entry, 32, FTW_DEPTH | FTW_PHYS | FTW_MOUNT);
    if (lstat(path, &st) == 0)
        run_quietly((char *const[]){"/bin/rm", "-rf", "--one-file-system", "--", (char *)path, NULL});
    return lstat(path, &st) == 0 ? -1 : 0;
}

/* The System V objects of uid listed in /proc/sysvipc/KIND (shm, msg or sem), removed: their ids are the
 * second column, their owners the column the header names "uid". */
static void remove_ipc_owned(const char *kind, uid_t uid)
{
    char path[64], line[512];
    snprintf(path, sizeof path, "/proc/sysvipc/%s", kind);
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    int uid_column = -1;
    if (fgets(line, sizeof line, f)) {
        int column = 0;
        for (char *word = strtok(line, " \t\n"); word; word = strtok(NULL, " \t\n"), column++)
            if (strcmp(word, "uid") == 0)
                uid_column = column;
    }
    while (uid_column > 1 && fgets(line, sizeof line, f)) {
        long id = -1, who = -1;
        int column = 0;
        for (char *word = strtok(line, " \t\n"); word; word = strtok(NULL, " \t\n"), column++) {
            if (column == 1)
                id = strtol(word, NULL, 10);
            if (column == uid_column)
                who = strtol(word, NULL, 10);
        }
        if (id < 0 || who != (long)uid)
            continue;
        if (kind[1] == 'h')
            shmctl((int)id, IPC_RMID, NULL);
        else if (kind[0] == 'm')
            msgctl((int)id, IPC_RMID, NULL);
        else
            semctl((int)id, 0, IPC_RMID);
    }
    fclose(f);
}

/* find (findutils), whose walk reaches any depth, where nftw stops at PATH_MAX. */
void scratch_remove_owned(uid_t uid)
{
    char user[32];
    snprintf(user, sizeof user, "%ld", (long)uid);
    run_quietly((char *const[]){"/usr/bin/find", "/tmp", "/var/tmp", "/dev/shm", "/run/lock", "/dev/mqueue", "-xdev",
                                "-mindepth", "1", "-user", user, "-delete", NULL});
    remove_ipc_owned("shm", uid);
    remove_ipc_owned("msg", uid);
    remove_ipc_owned("sem", uid);
}

/* Writes text into the file at path, if it can. */
static void write_file(const char *path, const char *text)
{
    int fd = open(path, O_WRONLY | O_TRUNC);
    if (fd < 0)
        return;
    if (write(fd, text, strlen(text)) < 0) {
        /* the limit stays: the clean-up after the run removes what was made */
    }
    close(fd);
}

int scratch_private_ipc(void)
{
    if (unshare(CLONE_NEWIPC) != 0)
        return -1;
    write_file("/proc/sys/kernel/shmmni", "0");
    write_file("/proc/sys/kernel/msgmni", "0");
    write_file("/proc/sys/kernel/sem", "0 0 0 0");
    write_file("/proc/sys/fs/mqueue/queues_max", "0");
    return 0;
}

int scratch_private_shm(void)
{
    if (unshare(CLONE_NEWNS) != 0)
        return -1;
    /* nothing mounted here reaches the grader's namespace */
    if (mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0 ||
        mount("rt-shm", "/dev/shm", "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC, "size=64m,mode=1777") != 0)
        return -1;
    return 0;
}

int scratch_private_tmp(const char *sandbox, const char *folder, uid_t uid, gid_t gid)
{
    /* the sandbox, kept open: the tmpfs hides it, and it comes back at its own path */
    int kept = open(sandbox, O_PATH | O_DIRECTORY | O_CLOEXEC);
    if (kept < 0)
        return -1;
    char from[64];
    snprintf(from, sizeof from, "/proc/self/fd/%d", kept);
    /* what is mounted, in order: undone from the last on should a step fail */
    const char *mounted[6];
    int n = 0;
    if (mount("rt-tmp", "/tmp", "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC, "size=64m,mode=1777") == 0 &&
        (mounted[n++] = "/tmp") &&
        mkdir(sandbox, 0711) == 0 && mount(from, sandbox, NULL, MS_BIND, NULL) == 0 && (mounted[n++] = sandbox) &&
        mkdir("/tmp/.run", 0700) == 0 && chown("/tmp/.run", uid, gid) == 0 &&
        mount("/tmp/.run", folder, NULL, MS_BIND, NULL) == 0 && (mounted[n++] = folder) &&
        mkdir("/tmp/.var-tmp", 0700) == 0 && chmod("/tmp/.var-tmp", 01777) == 0 &&
        mount("/tmp/.var-tmp", "/var/tmp", NULL, MS_BIND, NULL) == 0 && (mounted[n++] = "/var/tmp") &&
        mkdir("/tmp/.run-lock", 0700) == 0 && chmod("/tmp/.run-lock", 01777) == 0 &&
        mount("/tmp/.run-lock", "/run/lock", NULL, MS_BIND, NULL) == 0 && (mounted[n++] = "/run/lock") &&
        mkdir("/tmp/.shm", 0700) == 0 && chmod("/tmp/.shm", 01777) == 0 &&
        mount("/tmp/.shm", "/dev/shm", NULL, MS_BIND, NULL) == 0 && (mounted[n++] = "/dev/shm")) {
        close(kept);
        return 0;
    }
    close(kept);
    while (n > 0) /* the folders as they were: the clean-up after the run removes what is left on disk */
        umount2(mounted[--n], MNT_DETACH);
    return -1;
}
