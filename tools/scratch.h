/* scratch.h - the grader's scratch folders, and what the tests leave behind.
 *
 * Every run of a graded test gets a folder of its own (its working folder,
 * HOME and TMPDIR), removed after it; with a user of its own (--user), the
 * files that user left in the world-writable folders (/tmp, /var/tmp,
 * /dev/shm, /run/lock, /dev/mqueue) go too, and its System V shared memory,
 * message queues and semaphores, so nothing carries from one test to the
 * next or stays after grading.  Removal never follows a link and never
 * leaves the folder's file system, and reaches folders at any depth.
 */
#ifndef RT_TOOLS_SCRATCH_H
#define RT_TOOLS_SCRATCH_H

#include <sys/types.h>

/* Removes path and everything below it; 0 on success. */
int scratch_remove(const char *path);

/* Removes every file and folder owned by uid below /tmp, /var/tmp,
 * /dev/shm, /run/lock and /dev/mqueue, and uid's System V IPC objects (the
 * user's processes must be gone). */
void scratch_remove_owned(uid_t uid);

/* In a test's process, as root, before it becomes the tests' user: an IPC
 * namespace of its own, in which no shared memory, message queue, semaphore
 * or POSIX queue can be made (such memory would sit outside RLIMIT_AS, and
 * what is made dies with the namespace).  -1 where the system allows no new
 * namespace (a container without CAP_SYS_ADMIN): scratch_remove_owned then
 * removes them after the run. */
int scratch_private_ipc(void);

/* In a test's process, as root, before it becomes the tests' user: a mount
 * namespace of its own, where /dev/shm is a tmpfs of its own of at most 64
 * MB, not executable: files there are held in memory, outside RLIMIT_AS
 * (two 1024 MB tests could take the machine's memory so, half of it on an
 * ordinary /dev/shm), and what is left there dies with the namespace.  -1
 * where the system allows no new namespace (a container without
 * CAP_SYS_ADMIN, whose /dev/shm is small: 64 MB in Docker): the /dev/shm
 * of all, which scratch_remove_owned clears after the run. */
int scratch_private_shm(void);

/* After scratch_private_shm, in the same process and namespace: /tmp a tmpfs
 * of its own of at most 64 MB, not executable, which holds the run's folder
 * (mounted on `folder`, owned by uid:gid), /var/tmp, /run/lock and /dev/shm,
 * with `sandbox`, a folder of /tmp, mounted back at its own path (the
 * suites' copies).  A file's size is limited (RLIMIT_FSIZE), the number of
 * files is not: 64 MB files written on disk, 5.6 GB in a test of 3 s, could
 * fill the machine's disk.  Every folder the test may write to is then one
 * of 64 MB in all, and no file written there can be mapped executable.  The
 * caller enters `folder` again (its working folder was the one on disk).
 * -1 where the system allows no new namespace: the folders of all, which
 * scratch_remove_owned clears after the run. */
int scratch_private_tmp(const char *sandbox, const char *folder, uid_t uid, gid_t gid);

#endif
