/* seal.h - what a test's process may not do, by a filter of system calls.
 *
 * seal(), in the process about to exec a test, installs a filter (seccomp)
 * that the test and every process it starts keep:
 *   - no network: socket() of any family but AF_UNIX fails (EACCES), and so
 *     does io_uring (ENOSYS), which could open a socket without that call.
 *     No test needs it, and with it a submission could ask a server (a
 *     student's own, running the hand-out's compiled reference) for its
 *     answers instead of computing them;
 *   - no code made at run time in memory: mmap() with PROT_EXEC of anonymous
 *     or writable memory, mprotect() adding PROT_EXEC, shmat() with
 *     SHM_EXEC and a personality that makes readable memory executable
 *     fail (EACCES), so that a submission cannot copy the hand-out's
 *     compiled reference into memory and run it.  A file mapped with
 *     PROT_EXEC still works, as the loader maps the libraries so: a file of
 *     those bytes, or a write through /proc/self/mem, is not refused
 *     (docs/instructor-guide.md, "What the grader guarantees");
 *   - no System V shared memory, message queue or semaphore and no POSIX
 *     message queue is made (shmget, msgget, semget, mq_open fail, EACCES):
 *     no test needs them, such memory sits outside RLIMIT_AS, and they
 *     would outlive the test (scratch.h removes any all the same);
 *   - no key is kept in the kernel's keyrings (add_key, request_key, keyctl
 *     fail, EACCES): the user's keyrings outlive every process of the user,
 *     even the user's deletion, so a key would carry from one test (or
 *     grading) to the next and stay behind after grading;
 *   - no user namespace (unshare and clone with CLONE_NEWUSER fail, EPERM,
 *     and clone3, whose flags the filter cannot read, ENOSYS: the C library
 *     then uses clone): in one a test may mount a tmpfs, memory outside
 *     RLIMIT_AS in a mount no clean-up sees (2 GiB a test were taken so);
 *   - no file held in memory without a folder (memfd_create fails, EACCES):
 *     its pages sit outside RLIMIT_AS as long as a descriptor holds it, and
 *     a test may open hundreds (2 GiB a test were taken so);
 *   - with one_process, no process but the test's own: fork, vfork and clone
 *     without CLONE_THREAD (posix_spawn, system) fail, EAGAIN, as at a limit
 *     on processes.  RLIMIT_AS is a process's: each child has one of its
 *     own, so that a test of three children took 2 GiB under a limit of 1;
 *     threads share their process's;
 *   - a system call of another ABI than the machine's own (32-bit calls on
 *     x86-64) kills the process.
 * Files, threads and pipes work as before.
 */
#ifndef RT_TOOLS_SEAL_H
#define RT_TOOLS_SEAL_H

/* 0, or -1 when the filter cannot be installed (a kernel without seccomp,
 * a machine other than x86-64 and aarch64). */
int seal(int one_process);

#endif
