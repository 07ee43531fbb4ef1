/* scratch.h - the grader's scratch folders, and what the tests leave behind.
 *
 * Every run of a graded test gets a folder of its own (its working folder,
 * HOME and TMPDIR), removed after it; with a user of its own (--user), the
 * files that user left in the world-writable folders (/tmp, /var/tmp,
 * /dev/shm, /run/lock) go too, so nothing carries from one test to the next or stays
 * after grading.  Removal never follows a link and never leaves the
 * folder's file system.
 */
#ifndef RT_TOOLS_SCRATCH_H
#define RT_TOOLS_SCRATCH_H

#include <sys/types.h>

/* Removes path and everything below it; 0 on success. */
int scratch_remove(const char *path);

/* Removes every file and folder owned by uid below /tmp, /var/tmp,
 * /dev/shm and /run/lock (the user's processes must be gone). */
void scratch_remove_owned(uid_t uid);

#endif
