/* seal.c - what a test's process may not do, by a filter of system calls (seal.h). */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS, SHM_EXEC */
#include "seal.h"

#include <errno.h>
#include <stddef.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/shm.h>
#include <sys/socket.h>
#include <sys/syscall.h>

#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/sched.h>
#include <linux/seccomp.h>

#ifndef SYS_clone3 /* headers older than the call: its number, the same on x86-64 and aarch64 */
#define SYS_clone3 435
#endif

#if defined(__x86_64__)
#define NATIVE_ABI AUDIT_ARCH_X86_64
#define OTHER_ABI 0x40000000 /* x32's system calls: numbers from here */
#elif defined(__aarch64__)
#define NATIVE_ABI AUDIT_ARCH_AARCH64
#endif

/* The filter's steps: load an argument's low 32 bits (an int or flags;
 * little-endian), jump over so many steps by a test, return.  Each system
 * call's steps end in a return, so the next call's test sees its number. */
#define ARG(k) BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, args[k]))
#define IF_EQUAL(value, yes, no) BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, (value), (yes), (no))
#define IF_BITS(bits, yes, no) BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, (bits), (yes), (no))
#define RETURN(action) BPF_STMT(BPF_RET | BPF_K, (action))
#define REFUSE(error) RETURN(SECCOMP_RET_ERRNO | (error))
#define ALLOW RETURN(SECCOMP_RET_ALLOW)

int seal(int one_process)
{
#ifdef NATIVE_ABI
    /* a process that is not a thread of the test's (fork, vfork, posix_spawn: clone without CLONE_THREAD) */
    const unsigned new_process = one_process ? SECCOMP_RET_ERRNO | EAGAIN : SECCOMP_RET_ALLOW;
    struct sock_filter code[] = {
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, arch)),
        IF_EQUAL(NATIVE_ABI, 1, 0),
        RETURN(SECCOMP_RET_KILL_PROCESS),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, nr)),
#ifdef OTHER_ABI
        BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, OTHER_ABI, 0, 1),
        RETURN(SECCOMP_RET_KILL_PROCESS),
#endif
        IF_EQUAL(SYS_io_uring_setup, 0, 1),
        REFUSE(ENOSYS),
#ifdef SYS_userfaultfd
        IF_EQUAL(SYS_userfaultfd, 0, 1), /* pages filled by the process itself: no test needs them */
        REFUSE(ENOSYS),
#endif
        IF_EQUAL(SYS_memfd_create, 0, 1), /* a file held in memory, outside RLIMIT_AS */
        REFUSE(EACCES),
        IF_EQUAL(SYS_socket, 0, 4), /* any family but AF_UNIX */
        ARG(0),
        IF_EQUAL(AF_UNIX, 0, 1),
        ALLOW,
        REFUSE(EACCES),
        /* PROT_EXEC of anonymous or writable memory, or of a shared mapping: mremap with an old size of 0
         * makes a second mapping of a shared one's pages (of /dev/zero: memory), which mprotect may make
         * writable, and what is written through it runs through the first */
        IF_EQUAL(SYS_mmap, 0, 8),
        ARG(2),
        IF_BITS(PROT_EXEC, 0, 5),
        IF_BITS(PROT_WRITE, 3, 0),
        ARG(3),
        IF_BITS(MAP_ANONYMOUS | MAP_SHARED, 1, 0), /* MAP_SHARED_VALIDATE holds MAP_SHARED's bit */
        ALLOW,
        REFUSE(EACCES),
        ALLOW,
        IF_EQUAL(SYS_mprotect, 1, 0), /* PROT_EXEC added */
        IF_EQUAL(SYS_pkey_mprotect, 0, 4),
        ARG(2),
        IF_BITS(PROT_EXEC, 0, 1),
        REFUSE(EACCES),
        ALLOW,
        IF_EQUAL(SYS_shmat, 0, 4), /* SHM_EXEC */
        ARG(2),
        IF_BITS(SHM_EXEC, 0, 1),
        REFUSE(EACCES),
        ALLOW,
        IF_EQUAL(SYS_shmget, 3, 0), /* no System V or POSIX IPC object made */
        IF_EQUAL(SYS_msgget, 2, 0),
        IF_EQUAL(SYS_semget, 1, 0),
        IF_EQUAL(SYS_mq_open, 0, 1),
        REFUSE(EACCES),
        IF_EQUAL(SYS_add_key, 2, 0), /* no key in the kernel's keyrings, which outlive every process */
        IF_EQUAL(SYS_request_key, 1, 0),
        IF_EQUAL(SYS_keyctl, 0, 1),
        REFUSE(EACCES),
        IF_EQUAL(SYS_clone3, 0, 1), /* its flags lie in memory, out of the filter's sight: the C library then uses clone */
        REFUSE(ENOSYS),
        IF_EQUAL(SYS_unshare, 0, 4), /* no user namespace, where a test may mount memory of its own */
        ARG(0),
        IF_BITS(CLONE_NEWUSER, 0, 1),
        REFUSE(EPERM),
        ALLOW,
        IF_EQUAL(SYS_clone, 0, 6), /* the same; and with one_process, threads only */
        ARG(0),
        IF_BITS(CLONE_NEWUSER, 0, 1),
        REFUSE(EPERM),
        IF_BITS(CLONE_THREAD, 0, 1),
        ALLOW,
        RETURN(new_process),
#ifdef SYS_fork /* x86-64's fork and vfork (aarch64 has only clone) */
        IF_EQUAL(SYS_fork, 1, 0),
        IF_EQUAL(SYS_vfork, 0, 1),
        RETURN(new_process),
#endif
        IF_EQUAL(SYS_personality, 0, 4), /* only asked, never set (READ_IMPLIES_EXEC) */
        ARG(0),
        IF_EQUAL(0xffffffff, 0, 1),
        ALLOW,
        REFUSE(EACCES),
        ALLOW,
    };
    struct sock_fprog filter = {(unsigned short)(sizeof code / sizeof code[0]), code};
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 || prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &filter) != 0)
        return -1;
    return 0;
#else
    (void)one_process;
    return -1;
#endif
}
