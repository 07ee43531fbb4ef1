/* scratch.c - the grader's scratch folders, and what the tests leave behind (scratch.h). */
#define _XOPEN_SOURCE 700 /* nftw */
#include "scratch.h"

#include <ftw.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

static int remove_entry(const char *path, const struct stat *st, int type, struct FTW *ftw)
{
    (void)st, (void)type, (void)ftw;
    remove(path);
    return 0;
}

int scratch_remove(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return 0;
    nftw(path, remove_entry, 32, FTW_DEPTH | FTW_PHYS | FTW_MOUNT);
    return lstat(path, &st) == 0 ? -1 : 0;
}

static uid_t owner;

static int remove_owned(const char *path, const struct stat *st, int type, struct FTW *ftw)
{
    (void)type;
    if (ftw->level > 0 && st->st_uid == owner)
        remove(path);
    return 0;
}

void scratch_remove_owned(uid_t uid)
{
    static const char *const shared[] = {"/tmp", "/var/tmp", "/dev/shm", "/run/lock"};
    owner = uid;
    for (size_t k = 0; k < sizeof shared / sizeof shared[0]; k++)
        nftw(shared[k], remove_owned, 32, FTW_DEPTH | FTW_PHYS | FTW_MOUNT);
}
