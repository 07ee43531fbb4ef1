/* offline.h - a test's process cut off the network.
 *
 * No test needs the network, and with it a submission could ask a server
 * for its answers (a student's own, running the hand-out's compiled
 * reference) instead of computing them.  offline(), in the process about to
 * exec a test, installs a filter of system calls (seccomp) that the test
 * and every process it starts keep: socket() of any family but AF_UNIX
 * fails (EACCES), and so does io_uring (ENOSYS), which could open a socket
 * without that call; a system call of another ABI than the machine's own
 * (32-bit calls on x86-64, which have a socketcall) kills the process.
 * Nothing else changes: files, threads and local pipes work as before.
 */
#ifndef RT_TOOLS_OFFLINE_H
#define RT_TOOLS_OFFLINE_H

/* 0, or -1 when the filter cannot be installed (a kernel without seccomp,
 * a machine other than x86-64 and aarch64). */
int offline(void);

#endif
