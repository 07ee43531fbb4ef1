/* grade.c - run each graded test in its own process and report the points.
 *
 *     grade [--timeout SECONDS] [--budget SECONDS] [--memory MB] [--json FILE]
 *           [--junit FILE] [--notes FILE] [--user NAME] [--require-full]
 *           CHAPTER SUITE REFERENCE BUILDLOG FLOAT FLOATLOG FLOATREFERENCE ...
 *     grade --clean    (standard input to output, for a terminal: see print_clean)
 *
 * Seven words per chapter: the chapter's name; SUITE, the test binary built
 * with the student's files of that chapter (missing when they did not
 * compile or were refused); REFERENCE, the same suite built from the
 * reference, which lists the tests and their points (`--list`); BUILDLOG,
 * the compiler's messages (shown: warnings do not cost points, errors fail
 * the chapter); FLOAT, FLOATLOG and FLOATREFERENCE, the same of the float
 * build (REAL=float), or "-" "-" "-".
 *
 * The verdict.  Every test runs twice, each in a child process of its own
 * with its output captured and a time limit: the reference's suite, then
 * the student's, each as `SUITE --only NAME --answers 3 --seed SEED` with a
 * seed drawn now.  Each writes on descriptor 3 what its checks compare and
 * its answers to inputs drawn from the seed (tests/answers.h), and the
 * grader decides from those two transcripts (judge.h): the process that ran
 * the student's code gives answers, never the verdict, so printing what
 * cmocka prints, exiting early, or replacing cmocka's functions passes
 * nothing, and a table of the suite's published inputs fails the inputs
 * drawn from the seed.  A test that crashes or hangs fails alone.  A test
 * the reference skips (the Cornell corpus is absent) counts neither way.
 * The float build runs each test again; its verdict is reported with the
 * test and in one line per chapter worth no points (with --require-full it
 * must pass too).
 *
 * Limits: every run is a session of its own (no controlling terminal to
 * type into), sealed (seal.h: no network to ask a server for answers, no
 * memory made executable to run a copy of the compiled reference in, no
 * IPC object that would outlive it, no file held in memory, and with --user
 * no process but its own, each of which would have a memory limit of its own) and
 * has its own folder (HOME, TMPDIR; the working folder
 * with --user), removed after it, at most --memory MB of memory (1024) and
 * files of 64 MB; the whole grading stops starting tests after --budget
 * seconds (3600), and the tests not run fail, said so.
 *
 * --user NAME (as root; the autograder) runs the student's tests as that
 * user: the student's suites are copied into a fresh folder under /tmp that
 * the user can run but not change, while the reference's suites run as the
 * grader, where that user can neither run them (to have them write its
 * records) nor reach them; the environment is emptied but for PATH, HOME, TMPDIR and
 * LANG, and after every run every process of that user is killed (and
 * reaped: the grader is the subreaper of the tests' orphans) and its files
 * in /tmp, /var/tmp, /dev/shm and /run/lock removed, so nothing it started (even
 * in a session or process group of its own) or left outlives its test.
 *
 * Writes a score table to stdout, a Gradescope results.json (--json; the
 * --notes file and the compiler's messages are its "output"; always valid
 * UTF-8) and a JUnit XML report (--junit).  Exits 0 when grading ran, 1 on
 * a usage or I/O problem or when there was nothing to grade, and with
 * --require-full also 1 when any point was lost.
 */
#define _DEFAULT_SOURCE /* setgroups */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pwd.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "judge.h"
#include "scratch.h"
#include "seal.h"

enum { OUTPUT_LIMIT = 16384 }; /* bytes of a test's output that are kept */

typedef enum { PASSED, FAILED, SKIPPED } verdict;

typedef struct {
    char *chapter, *name;
    int points, score;
    int info; /* a line worth no points (the float build): not in the table's counts */
    verdict result;
    char *output; /* what the test printed, then the grader's note */
} test_result;

static test_result *results;
static size_t n_results, cap_results;

static void *xrealloc(void *p, size_t size)
{
    p = realloc(p, size ? size : 1);
    if (!p) {
        fprintf(stderr, "grade: out of memory\n");
        exit(1);
    }
    return p;
}

static char *xstrdup(const char *s)
{
    size_t n = strlen(s) + 1;
    return memcpy(xrealloc(NULL, n), s, n);
}

/* A growing string. */
typedef struct {
    char *s;
    size_t len, cap;
    int truncated;
} buffer;

static void buf_add(buffer *b, const char *data, size_t n)
{
    if (b->len + n + 1 > b->cap) {
        b->cap = 2 * (b->len + n + 1);
        b->s = xrealloc(b->s, b->cap);
    }
    memcpy(b->s + b->len, data, n);
    b->len += n;
    b->s[b->len] = '\0';
}

static void buf_str(buffer *b, const char *s) { buf_add(b, s, strlen(s)); }

/* Adds what a test or the compiler wrote: a NUL byte becomes '?', as
 * everything after it would be lost to the grader, which reads the text as
 * a string (its own note of why a test failed, which it adds after). */
static void buf_add_text(buffer *b, char *data, size_t n)
{
    for (char *z = memchr(data, '\0', n); z; z = memchr(z, '\0', n - (size_t)(z - data)))
        *z = '?';
    buf_add(b, data, n);
}

static char *buf_take(buffer *b)
{
    if (!b->s)
        buf_add(b, "", 0);
    return b->s;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The user the tests run as (--user), and the folders of the runs. */
static int as_user;
static uid_t user_uid;
static gid_t user_gid;
static char sandbox[64]; /* the suites' copies and one folder per run */
static int runs;         /* runs so far: the next run's folder */

/* Limits of every run of a graded test: memory (address space) and the size
 * of a file it writes; and the end of the whole grading's time (--budget). */
static long memory_mb = 1024, file_mb = 64;
static double budget_end;

enum { ANSWERS_FD = 3 };                /* where a suite writes its records (tests/answers.h) */
enum { ANSWERS_LIMIT = 16 << 20 };      /* bytes of records kept: more fails the test */

/* 16 hex digits from /dev/urandom: the seed of a test's inputs drawn at grading time. */
static void make_seed(char seed[17])
{
    unsigned char bytes[8] = {0};
    int fd = open("/dev/urandom", O_RDONLY);
    if (fd < 0 || read(fd, bytes, sizeof bytes) != (ssize_t)sizeof bytes) {
        fprintf(stderr, "grade: cannot read /dev/urandom\n");
        exit(1);
    }
    close(fd);
    for (int k = 0; k < 8; k++)
        snprintf(seed + 2 * k, 3, "%02x", bytes[k]);
}

/* Whether a process of the tests' user is still there (/proc/PID/status:
 * any of its real, effective, saved or file-system user ids). */
static int user_processes_left(void)
{
    DIR *proc = opendir("/proc");
    if (!proc)
        return 1; /* not known: taken as some left, so that nothing is removed as root */
    int found = 0;
    struct dirent *e;
    while (!found && (e = readdir(proc)) != NULL) {
        if (e->d_name[0] < '1' || e->d_name[0] > '9')
            continue;
        char path[300], line[256];
        snprintf(path, sizeof path, "/proc/%s/status", e->d_name);
        FILE *f = fopen(path, "r");
        if (!f)
            continue;
        while (fgets(line, sizeof line, f)) {
            long id[4] = {-1, -1, -1, -1};
            if (strncmp(line, "Uid:", 4) == 0 &&
                sscanf(line + 4, "%ld %ld %ld %ld", &id[0], &id[1], &id[2], &id[3]) == 4)
                for (int k = 0; k < 4; k++)
                    found |= id[k] == (long)user_uid;
        }
        fclose(f);
    }
    closedir(proc);
    return found;
}

/* Kills every process of the tests' user: a child that becomes that user
 * sends SIGKILL to every process it may signal (kill(-1)), which are exactly
 * that user's processes, whatever session or process group they moved to.
 * That child is itself a process of the user, which the others may signal
 * between its setuid and its kill: it blocks every signal it can, one
 * stopped (SIGSTOP) is killed, not waited for, and the rounds go on until
 * no process of the user is left (the test's orphans, which come to the
 * grader, reaped) or two seconds have passed.  0 when some are left:
 * then nothing of the user's is removed as root, since a process of the user
 * could swap a folder for a link to elsewhere while root removes. */
static int kill_user_processes(void)
{
    const double until = now() + 2;
    do {
        pid_t pid = fork();
        if (pid == 0) {
            sigset_t all; /* only SIGSTOP and SIGKILL, which cannot be blocked, reach it */
            sigfillset(&all);
            sigprocmask(SIG_BLOCK, &all, NULL);
            if (setgid(user_gid) == 0 && setuid(user_uid) == 0)
                kill(-1, SIGKILL);
            _exit(0);
        }
        int status;
        while (pid > 0 && waitpid(pid, &status, WUNTRACED) == pid && WIFSTOPPED(status))
            kill(pid, SIGKILL); /* stopped by a process of the user: it may have killed nothing */
        while (waitpid(-1, NULL, WNOHANG) > 0) /* the test's orphans, killed: no zombie counts */
            ;
        if (!user_processes_left())
            return 1;
        struct timespec pause = {0, 1000 * 1000};
        nanosleep(&pause, NULL);
    } while (now() < until);
    return 0;
}

/* Waits for the test's processes that were left without a parent and came
 * to the grader (a subreaper, see main), all killed by now: no zombie of
 * theirs stays behind.  A short while at most. */
static void reap_orphans(void)
{
    const double until = now() + 0.2;
    while (now() < until) {
        pid_t pid = waitpid(-1, NULL, WNOHANG);
        if (pid < 0) /* no child left */
            return;
        if (pid == 0) {
            struct timespec pause = {0, 2 * 1000 * 1000};
            nanosleep(&pause, NULL);
        }
    }
}

/* Appends what is waiting on fd to b, up to limit bytes (beyond: truncated);
 * 0 at the end of the pipe. */
static int drain(int fd, buffer *b, size_t limit)
{
    char chunk[4096];
    ssize_t n = read(fd, chunk, sizeof chunk);
    if (n > 0) {
        size_t keep = b->len < limit ? limit - b->len : 0;
        if ((size_t)n > keep)
            b->truncated = 1;
        buf_add_text(b, chunk, (size_t)n < keep ? (size_t)n : keep);
        return 1;
    }
    return n < 0 && errno == EINTR;
}

/* The lines a test printed, from b->s + from on, made to read as its own:
 * one that begins as the grader's notes do ("grade: ", "float build") gets
 * "the test printed: " before it, and the last ends in a newline, so that
 * the grader's note that follows starts a line of its own.  A line that
 * holds those words anywhere is marked so: one after a space, or after a
 * character that shows as nothing (U+200B), read as the grader's too (and
 * the print and the reports show such a character as '?', U+FFFD: see
 * format_control).  Otherwise a test
 * could print "grade: passed" and end its output without a newline, and the
 * terminal then showed its line as the grader's and left out the grader's
 * own, glued to the test's fifth line (print_reason). */
static void own_lines(buffer *b, size_t from)
{
    static const char *const reserved[] = {"grade: ", "float build (REAL=float)", NULL};
    if (b->len <= from)
        return;
    buffer mine = {0};
    buf_add(&mine, b->s, from);
    for (size_t at = from; at < b->len;) {
        const char *end = memchr(b->s + at, '\n', b->len - at);
        size_t n = end ? (size_t)(end - (b->s + at)) + 1 : b->len - at;
        int marked = 0; /* the reserved words anywhere in the line: after a space or a character
                           that shows as nothing, the line read as the grader's all the same */
        for (int k = 0; reserved[k] && !marked; k++)
            for (size_t i = at, len = strlen(reserved[k]); !marked && i + len <= at + n; i++)
                marked = memcmp(b->s + i, reserved[k], len) == 0;
        if (marked)
            buf_str(&mine, "the test printed: ");
        buf_add(&mine, b->s + at, n);
        at += n;
    }
    if (mine.s[mine.len - 1] != '\n')
        buf_str(&mine, "\n");
    mine.truncated = b->truncated;
    free(b->s);
    *b = mine;
}

/* What a run is: the reference's --list (trusted, as it is); a test of the
 * reference's suite (no student code: limits and a folder of its own, and
 * with --user the emptied environment, but not that user, whose processes
 * then cannot run it or reach it); a test of the student's suite (all that,
 * and with --user as that user). */
typedef enum { RUN_TRUSTED, RUN_REFERENCE, RUN_STUDENT } run_kind;

/* In the child: the limits, the folder, the user and the environment of a
 * test's run, then exec. */
static void exec_test(char *const argv[], const char *folder, run_kind kind)
{
    struct rlimit memory = {(rlim_t)memory_mb << 20, (rlim_t)memory_mb << 20};
    struct rlimit file = {(rlim_t)file_mb << 20, (rlim_t)file_mb << 20};
    setrlimit(RLIMIT_AS, &memory);
    setrlimit(RLIMIT_FSIZE, &file);
    char home[128], tmpdir[128];
    snprintf(home, sizeof home, "HOME=%s", folder);
    snprintf(tmpdir, sizeof tmpdir, "TMPDIR=%s", folder);
    if (as_user) {
        if (chdir(folder) != 0) {
            fprintf(stderr, "grade: cannot enter the test's folder\n");
            _exit(127);
        }
        if (kind == RUN_STUDENT) {
            struct rlimit procs = {256, 256};
            setrlimit(RLIMIT_NPROC, &procs); /* threads count too */
            /* What waits in a socket's or pipe's buffer is the kernel's memory, outside RLIMIT_AS, some
             * 200 KiB a local socket: 2 GiB were held so under 20000 descriptors, 28 MiB at most under 256. */
            struct rlimit files = {256, 256};
            setrlimit(RLIMIT_NOFILE, &files);
            scratch_private_ipc();           /* no System V or POSIX IPC (scratch.h) */
            const int own_mounts = scratch_private_shm() == 0; /* a /dev/shm of its own, of 64 MB */
            /* a /tmp of its own, of 64 MB, not executable: its folder, /var/tmp, /run/lock, /dev/shm; only
             * in a mount namespace of its own, never over the grader's /tmp */
            if (own_mounts && scratch_private_tmp(sandbox, folder, user_uid, user_gid) == 0 && chdir(folder) != 0) {
                fprintf(stderr, "grade: cannot enter the test's folder\n");
                _exit(127);
            }
            if (setgroups(0, NULL) != 0 || setgid(user_gid) != 0 || setuid(user_uid) != 0 || setuid(0) == 0) {
                fprintf(stderr, "grade: cannot become the tests' user\n");
                _exit(127);
            }
        }
        if (seal(kind == RUN_STUDENT) != 0) { /* no network, no code made at run time, one process (seal.h) */
            fprintf(stderr, "grade: cannot seal the test (seccomp)\n");
            _exit(127);
        }
        char *env[] = {"PATH=/usr/bin:/bin", home, tmpdir, "LANG=C.UTF-8", NULL};
        execve(argv[0], argv, env);
    } else { /* a student's own machine: the environment as it is, HOME and TMPDIR of the run's own */
        putenv(home);
        putenv(tmpdir);
        seal(0); /* where it can: nothing there is sealed against the student, whose own machine it is */
        execv(argv[0], argv);
    }
}

/* Runs argv with stdin from /dev/null and stdout+stderr captured (the first
 * OUTPUT_LIMIT bytes), in a session of its own (its process group, no
 * controlling terminal), killed after `timeout`
 * seconds.  An untrusted run (a test) has the limits above, a folder of its
 * own (working folder with --user, HOME, TMPDIR) removed afterwards, and
 * with --user runs as that user, whose every process and file in the shared
 * folders is gone when it returns.  With `answers`, the child's descriptor
 * ANSWERS_FD is a pipe whose records go there.  Returns the wait status, or
 * -1 when it timed out (or could not be started: then the reason is in the
 * output). */
static int run(char *const argv[], double timeout, buffer *out, run_kind kind, buffer *answers)
{
    const size_t start = out->len; /* the test's output starts here */
    int fds[2], ans[2] = {-1, -1};
    char folder[128] = "";
    const int student = kind == RUN_STUDENT;
    if (kind != RUN_TRUSTED) {
        snprintf(folder, sizeof folder, "%s/run-%d", sandbox, ++runs);
        if (mkdir(folder, 0700) != 0 || (as_user && student && chown(folder, user_uid, user_gid) != 0)) {
            buf_str(out, "grade: cannot make the test's folder\n");
            return -1;
        }
    }
    if (pipe(fds) != 0 || (answers && pipe(ans) != 0)) {
        buf_str(out, "grade: pipe failed\n");
        scratch_remove(folder);
        return -1;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        for (int k = 0; k < 2; k++) {
            close(fds[k]);
            if (answers)
                close(ans[k]);
        }
        buf_str(out, "grade: fork failed\n");
        scratch_remove(folder);
        return -1;
    }
    if (pid == 0) {
        /* A session of its own, so a process group too, and no controlling
         * terminal: a test cannot type into the terminal the grading runs in
         * (TIOCSTI on /dev/tty), whose shell, root's, would run the line. */
        if (setsid() < 0) {
            fprintf(stderr, "grade: cannot start a session for the test\n");
            _exit(127);
        }
        int null = open("/dev/null", O_RDONLY);
        if (null >= 0)
            dup2(null, STDIN_FILENO);
        dup2(fds[1], STDOUT_FILENO);
        dup2(fds[1], STDERR_FILENO);
        if (answers)
            dup2(ans[1], ANSWERS_FD);
        for (int fd = answers ? ANSWERS_FD + 1 : ANSWERS_FD; fd < 1024; fd++)
            close(fd); /* nothing of the grader's stays open */
        struct rlimit no_core = {0, 0};
        setrlimit(RLIMIT_CORE, &no_core);
        unsetenv("CMOCKA_MESSAGE_OUTPUT"); /* cmocka's plain report */
        unsetenv("CMOCKA_XML_FILE");
        alarm((unsigned)timeout + 2); /* a second guard, should the grader itself die */
        if (kind != RUN_TRUSTED)
            exec_test(argv, folder, kind);
        else
            execv(argv[0], argv);
        fprintf(stderr, "grade: cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    /* (No setpgid here as well: made a group's leader first, the child could
     * not start its session.  It does so before anything else.) */
    close(fds[1]);
    if (answers)
        close(ans[1]);
    const double deadline = now() + timeout;
    int open_out = 1, open_ans = answers != NULL, status = 0, timed_out = 0;
    pid_t done = 0;
    while (!done) {
        double left = deadline - now();
        if (left <= 0) {
            timed_out = 1;
            break;
        }
        struct pollfd p[2] = {{open_out ? fds[0] : -1, POLLIN, 0}, {open_ans ? ans[0] : -1, POLLIN, 0}};
        /* A short wait, so that an exit is seen even while something the
         * test started still holds a pipe open. */
        if (poll(p, 2, left < 0.05 ? (int)(left * 1000) + 1 : 50) > 0) {
            if (p[0].revents)
                open_out = drain(fds[0], out, OUTPUT_LIMIT);
            if (p[1].revents)
                open_ans = drain(ans[0], answers, ANSWERS_LIMIT);
        }
        done = waitpid(pid, &status, WNOHANG);
        if (done < 0) {
            status = 0;
            break;
        }
    }
    if (timed_out) {
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
    }
    kill(-pid, SIGKILL); /* anything the test left running */
    int stopped = 1;
    if (student && as_user) {
        stopped = kill_user_processes(); /* also what left the process group */
        reap_orphans();
    }
    /* Read what is left, without waiting for any stray grandchild (nor
     * reading for ever what one that escaped the process group writes). */
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    for (int k = 0; k < 4096 && open_out && drain(fds[0], out, OUTPUT_LIMIT); k++)
        ;
    close(fds[0]);
    if (student)
        own_lines(out, start);
    if (answers) {
        fcntl(ans[0], F_SETFL, O_NONBLOCK);
        for (int k = 0; k < 8192 && open_ans && drain(ans[0], answers, ANSWERS_LIMIT); k++)
            ;
        close(ans[0]);
    }
    if (kind != RUN_TRUSTED && stopped) {
        scratch_remove(folder);
        if (student && as_user)
            scratch_remove_owned(user_uid);
    } else if (!stopped) {
        buf_str(out, "\ngrade: processes of the tests' user outlived the clean-up; their files were not removed\n");
    }
    if (out->truncated)
        buf_str(out, "\n[output truncated]\n");
    return timed_out ? -1 : status;
}

/* Seconds left of the grading's time budget. */
static double budget_left(void) { return budget_end - now(); }

static void add_result(const char *chapter, const char *name, int points, int info, verdict v, const char *output)
{
    if (n_results == cap_results) {
        cap_results = cap_results ? 2 * cap_results : 32;
        results = xrealloc(results, cap_results * sizeof *results);
    }
    results[n_results++] = (test_result){xstrdup(chapter), xstrdup(name), points, v == PASSED ? points : 0,
                                         info, v, xstrdup(output)};
}

static char *read_file(const char *path)
{
    buffer b = {0};
    FILE *f = fopen(path, "rb");
    if (f) {
        char chunk[4096];
        size_t n;
        while ((n = fread(chunk, 1, sizeof chunk, f)) > 0 && b.len < OUTPUT_LIMIT)
            buf_add_text(&b, chunk, n);
        fclose(f);
    }
    return buf_take(&b);
}

static int utf8_length(const unsigned char *p);

/* Whether the UTF-8 sequence at p, of len bytes, sets the direction of text
 * (U+061C, U+200E, U+200F, U+202A to U+202E, U+2066 to U+2069): an override
 * turns the rest of its line around on screen, in a terminal that follows
 * them and in a browser, so that a test's line, or the compiler's quote of a
 * submitted line, would show other words than it holds; or is a format
 * character that shows as nothing (U+00AD, U+034F, U+180E, U+200B to U+200D,
 * U+2060 to U+2064, U+206A to U+206F, U+FEFF, U+FFF9 to U+FFFB, the tags
 * U+E0001 and U+E0020 to U+E007F): before "grade: passed" it made a test's
 * line read as the grader's note, which a test's line may not begin as
 * (own_lines), and inside the words it hid them from that comparison. */
static int format_control(const unsigned char *p, int len)
{
    if (len == 2)
        return (p[0] == 0xD8 && p[1] == 0x9C) || (p[0] == 0xC2 && p[1] == 0xAD) || (p[0] == 0xCD && p[1] == 0x8F);
    if (len == 4) /* the tags: U+E0001, U+E0020 to U+E007F */
        return p[0] == 0xF3 && p[1] == 0xA0 && ((p[2] == 0x80 && (p[3] == 0x81 || p[3] >= 0xA0)) || p[2] == 0x81);
    return len == 3 && ((p[0] == 0xE2 && ((p[1] == 0x80 && p[2] >= 0x8B && p[2] <= 0x8F) ||
                                          (p[1] == 0x80 && p[2] >= 0xAA && p[2] <= 0xAE) ||
                                          (p[1] == 0x81 && p[2] >= 0xA0 && p[2] <= 0xAF && p[2] != 0xA5))) ||
                        (p[0] == 0xE1 && p[1] == 0xA0 && p[2] == 0x8E) ||
                        (p[0] == 0xEF && p[1] == 0xBB && p[2] == 0xBF) ||
                        (p[0] == 0xEF && p[1] == 0xBF && p[2] >= 0xB9 && p[2] <= 0xBB));
}

/* Prints at most n bytes of s, a text of the test's or the compiler's, for a
 * terminal: a control character but tab and newline, a C1 control (U+0080
 * to U+009F, which terminals obey too), a control of the text's direction or
 * a character that shows as nothing (format_control) and a byte that is not
 * well-formed UTF-8 each as '?', so that no escape sequence of a submission's
 * reaches the terminal (to clear it, or hide the score table that follows). */
static void print_clean(const char *s, size_t n)
{
    const unsigned char *p = (const unsigned char *)s, *end = p + n;
    while (p < end && *p) {
        int len = utf8_length(p);
        if (len == 0 || (len == 1 && ((*p < 0x20 && *p != '\t' && *p != '\n') || *p == 0x7F)) ||
            (p[0] == 0xC2 && p[1] <= 0x9F) || format_control(p, len) || p + len > end) {
            putchar('?');
            p += len ? len : 1;
        } else {
            fwrite(p, 1, (size_t)len, stdout);
            p += len;
        }
    }
}

/* Prints the lines of a failed test's output that say why: at most four of
 * the test's messages (its own, cmocka's ERROR and LINE lines), then the
 * grader's notes ("grade: ...") and the float build's verdict, which are
 * never left out; each cut at 400 characters. */
static void print_reason(const char *output)
{
    static const char *const framing[] = {"[==", "[ RUN", "[       OK", "[  FAILED", "[  PASSED", "[  SKIPPED",
                                          " 1 FAILED TEST", NULL};
    static const char *const always[] = {"grade: ", "float build (REAL=float)", NULL};
    for (int pass = 0; pass < 2; pass++) { /* the test's messages, then the grader's lines */
        int shown = 0;
        for (const char *line = output; *line;) {
            const char *end = strchr(line, '\n');
            size_t n = end ? (size_t)(end - line) : strlen(line);
            int graders = 0, show = n > 0;
            for (int k = 0; always[k]; k++)
                graders |= strncmp(line, always[k], strlen(always[k])) == 0;
            for (int k = 0; show && framing[k]; k++)
                show = strncmp(line, framing[k], strlen(framing[k])) != 0;
            if (show && graders == pass && (pass == 1 || shown < 4)) {
                /* An unfinished exercise's line (common/exercise.c) up to its file: what the
                 * line goes on to say about images and REFERENCE= is for the renderers. */
                size_t shown_n = n;
                const char *cut = strstr(line, " is still an exercise (") ? strstr(line, "); it returns") : NULL;
                if (cut && cut < line + n)
                    shown_n = (size_t)(cut - line) + 1;
                printf("        ");
                print_clean(line, shown_n > 400 ? 400 : shown_n);
                putchar('\n');
                shown++;
            }
            line += n + (end != NULL);
        }
    }
}

/* The results' "output": the --notes file, then the compiler's messages. */
static buffer summary;
static int float_failures; /* tests that failed in the float build */

/* Runs test `name` of the reference's suite and of the student's (`suite`),
 * with the same seed for the inputs drawn at grading time, and judges the
 * student's records against the reference's (judge.h): the verdict, with
 * what the student's test printed and the grader's note in *out. */
static verdict run_test(const char *suite, const char *reference, const char *name, double timeout, buffer *out)
{
    double left = budget_left();
    if (left < 1) {
        buf_str(out, "grade: not run: the grading's time budget was used up by the tests before\n");
        return FAILED;
    }
    if (timeout > left)
        timeout = left;
    char seed[17], fd[8];
    make_seed(seed);
    snprintf(fd, sizeof fd, "%d", ANSWERS_FD);
    char note[700] = "";
    char *ref_argv[] = {(char *)reference, "--only", (char *)name, "--answers", fd, "--seed", seed, NULL};
    buffer ref_out = {0}, ref_answers = {0}, answers = {0};
    int ref_status = run(ref_argv, timeout, &ref_out, RUN_REFERENCE, &ref_answers);
    judge_verdict before = judge(buf_take(&ref_answers), "", note, sizeof note);
    const char *why = before == JUDGE_SKIPPED && ref_out.s ? strstr(ref_out.s, "note: ") : NULL;
    if (why) /* why the reference skipped (the course's scenes not found): the suite's note */
        buf_add(out, why, strcspn(why, "\n") + 1);
    free(ref_out.s);
    if (before == JUDGE_SKIPPED || before == JUDGE_BROKEN || ref_status < 0) {
        free(ref_answers.s);
        if (before == JUDGE_SKIPPED)
            return SKIPPED;
        buf_str(out, "grade: ");
        buf_str(out, ref_status < 0 ? "the reference did not finish this test in time (a problem of the grader: "
                                      "tell the course staff)" : note);
        buf_str(out, "\n");
        return FAILED;
    }
    char *argv[] = {(char *)suite, "--only", (char *)name, "--answers", fd, "--seed", seed, NULL};
    int status = run(argv, timeout, out, RUN_STUDENT, &answers);
    verdict v = FAILED;
    if (answers.truncated)
        snprintf(note, sizeof note, "more than %d bytes of records", ANSWERS_LIMIT);
    else if (status >= 0 && judge(buf_take(&ref_answers), buf_take(&answers), note, sizeof note) == JUDGE_PASSED)
        v = PASSED;
    char line[800] = "";
    if (status < 0)
        snprintf(line, sizeof line, "grade: timed out after %g s (an endless loop?)\n", timeout);
    else if (WIFSIGNALED(status))
        snprintf(line, sizeof line, "grade: crashed: %s (signal %d)%s\n", strsignal(WTERMSIG(status)),
                 WTERMSIG(status), WTERMSIG(status) == SIGXFSZ ? ": a file beyond the size limit" : "");
    else if (v == FAILED)
        snprintf(line, sizeof line, "grade: failed: %s\n", note);
    buf_str(out, line);
    free(ref_answers.s);
    free(answers.s);
    return v;
}

/* A file's text, "" when it is missing or empty. */
static char *log_text(const char *path) { return strcmp(path, "-") == 0 ? xstrdup("") : read_file(path); }

/* The files of one chapter (seven words of the command line); with --user
 * the student's suites are run from copies in the sandbox. */
typedef struct {
    const char *chapter, *suite, *reference, *buildlog, *float_suite, *float_log, *float_reference;
} chapter_files;

static int grade_chapter(const chapter_files *c, double timeout)
{
    const char *chapter = c->chapter, *suite = c->suite, *reference = c->reference, *float_suite = c->float_suite;
    buffer listing = {0};
    char *list_argv[] = {(char *)reference, "--list", NULL};
    int status = run(list_argv, timeout, &listing, RUN_TRUSTED, NULL);
    if (status < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "grade: %s --list failed:\n%s", reference, buf_take(&listing));
        return 1;
    }
    int built = access(suite, X_OK) == 0;
    int with_float = strcmp(float_suite, "-") != 0;
    int float_built = with_float && access(float_suite, X_OK) == 0;
    char *log = log_text(c->buildlog), *flog = log_text(c->float_log);
    printf("%s%s\n", chapter, built ? "" : ": the student's files do not compile or were refused; every test fails");
    if (built && *log) { /* warnings: shown, not counted */
        printf("  compiler messages (not counted):\n");
        print_clean(log, strlen(log));
        buf_str(&summary, "\n");
        buf_str(&summary, chapter);
        buf_str(&summary, ": the compiler's messages for your files (warnings cost no points; fix them):\n");
        buf_str(&summary, log);
    }
    if (with_float && !float_built && built) {
        printf("  the float build (REAL=float) does not compile:\n");
        print_clean(flog, strlen(flog));
        buf_str(&summary, "\n");
        buf_str(&summary, chapter);
        buf_str(&summary, ": your files do not compile in the float build (REAL=float):\n");
        buf_str(&summary, flog);
    }
    buffer float_failed = {0};
    int float_tests = 0, float_passed = 0;
    char *save = NULL;
    for (char *line = strtok_r(buf_take(&listing), "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        char name[256];
        int points;
        if (sscanf(line, "%255s %d", name, &points) != 2) {
            fprintf(stderr, "grade: %s --list: cannot read '%s'\n", reference, line);
            return 1;
        }
        buffer out = {0};
        verdict v = FAILED;
        if (!built) {
            buf_str(&out, "grade: the student's files did not compile or were refused:\n");
            buf_str(&out, log);
        } else {
            v = run_test(suite, c->reference, name, timeout, &out);
        }
        if (with_float && v != SKIPPED) {
            buffer fout = {0};
            verdict fv = float_built ? run_test(float_suite, c->float_reference, name, timeout, &fout) : FAILED;
            if (fv != SKIPPED) {
                float_tests++;
                float_passed += fv == PASSED;
            }
            buf_str(&out, fv == PASSED    ? "float build (REAL=float): passed\n"
                          : fv == SKIPPED ? "float build (REAL=float): skipped\n"
                          : !float_built  ? "float build (REAL=float): does not compile (not scored)\n"
                          : v == PASSED   ? "float build (REAL=float): FAILED (not scored):\n"
                                          : "float build (REAL=float): failed too (not scored)\n");
            if (fv == FAILED) {
                buf_str(&float_failed, "  ");
                buf_str(&float_failed, name);
                buf_str(&float_failed, "\n");
                if (float_built && v == PASSED) /* only then does its output tell something new */
                    buf_str(&out, buf_take(&fout));
            }
            free(fout.s);
        }
        add_result(chapter, name, points, 0, v, buf_take(&out));
        printf("  %s  %-50s %3d/%d\n", v == PASSED ? "pass" : v == SKIPPED ? "skip" : "FAIL", name,
               v == PASSED ? points : 0, v == SKIPPED ? 0 : points);
        if (v == FAILED && built)
            print_reason(out.s);
        if (v == SKIPPED && out.s) { /* why (run_test kept the suite's note) */
            printf("        ");
            print_clean(out.s, strlen(out.s) > 400 ? 400 : strlen(out.s));
        }
        free(out.s);
    }
    if (with_float) { /* one line for the float build, worth nothing */
        char name[80];
        snprintf(name, sizeof name, "float build (REAL=float): %d of %d tests pass", float_passed, float_tests);
        buffer out = {0};
        if (float_passed < float_tests) {
            buf_str(&out, "These tests pass in the double build but not in the float build; they cost no "
                          "points, but look for a constant or a function that is not `real` (1e-9, sqrt "
                          "instead of real_sqrt, double):\n");
            buf_str(&out, buf_take(&float_failed));
        }
        add_result(chapter, name, 0, 1, float_passed == float_tests ? PASSED : FAILED, buf_take(&out));
        printf("  %s  %-50s %3d/%d\n", float_passed == float_tests ? "pass" : "FAIL", name, 0, 0);
        float_failures += float_tests - float_passed;
        free(out.s);
    }
    free(float_failed.s);
    free(log);
    free(flog);
    free(listing.s);
    return 0;
}

/* The length of the well-formed UTF-8 sequence at p (1 to 4), or 0: no
 * overlong form, no surrogate, nothing above U+10FFFF, none cut short. */
static int utf8_length(const unsigned char *p)
{
    unsigned c = p[0];
    if (c < 0x80)
        return 1;
    int n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    unsigned lo = 0x80, hi = 0xBF; /* the second byte's range */
    if (c == 0xE0)
        lo = 0xA0;
    else if (c == 0xED)
        hi = 0x9F;
    else if (c == 0xF0)
        lo = 0x90;
    else if (c == 0xF4)
        hi = 0x8F;
    if (n == 0 || p[1] < lo || p[1] > hi)
        return 0;
    for (int k = 2; k < n; k++)
        if ((p[k] & 0xC0) != 0x80)
            return 0;
    return n;
}

/* Writes s as the body of a JSON string (or XML text when xml): control
 * characters escaped (XML: replaced), and every byte that is not part of
 * well-formed UTF-8 replaced by U+FFFD, so the file is always valid UTF-8;
 * a control of the text's direction or a character that shows as nothing
 * (format_control) is replaced too. */
static void put_escaped(FILE *f, const char *s, int xml)
{
    const unsigned char *p = (const unsigned char *)s;
    while (*p) {
        unsigned c = *p;
        int n = utf8_length(p);
        if (n == 0) {
            fputs("\xEF\xBF\xBD", f); /* U+FFFD, the replacement character */
            p++;
            continue;
        }
        if (n > 1) {
            if (format_control(p, n) || (xml && n == 3 && p[0] == 0xEF && p[1] == 0xBF && p[2] >= 0xBE))
                fputs("\xEF\xBF\xBD", f); /* U+FFFD: the direction of text is not the test's to set, and
                                                XML 1.0 allows no U+FFFE or U+FFFF */
            else
                fwrite(p, 1, (size_t)n, f);
            p += n;
            continue;
        }
        if (xml) {
            switch (c) {
            case '&': fputs("&amp;", f); break;
            case '<': fputs("&lt;", f); break;
            case '>': fputs("&gt;", f); break;
            case '"': fputs("&quot;", f); break;
            case '\'': fputs("&apos;", f); break;
            default: fputc((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F ? '?' : (int)c, f);
            }
        } else {
            switch (c) {
            case '"': fputs("\\\"", f); break;
            case '\\': fputs("\\\\", f); break;
            case '\n': fputs("\\n", f); break;
            case '\r': fputs("\\r", f); break;
            case '\t': fputs("\\t", f); break;
            default:
                if (c < 0x20 || c == 0x7F)
                    fprintf(f, "\\u%04x", c);
                else
                    fputc((int)c, f);
            }
        }
        p++;
    }
}

static int write_json(const char *path, int score, int max_score)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return 1;
    fprintf(f, "{\n  \"score\": %d,\n  \"max_score\": %d,\n  \"output\": \"", score, max_score);
    put_escaped(f, buf_take(&summary), 0);
    fputs("\",\n  \"tests\": [", f);
    for (size_t k = 0; k < n_results; k++) {
        const test_result *t = &results[k];
        fprintf(f, "%s\n    {\"name\": \"", k ? "," : "");
        put_escaped(f, t->chapter, 0);
        fputs(": ", f);
        put_escaped(f, t->name, 0);
        const char *status = t->result == PASSED ? "\"status\": \"passed\", "
                             : t->result == FAILED ? "\"status\": \"failed\", "
                                                   : "";
        fprintf(f, "\", \"number\": \"%zu\", \"score\": %d, \"max_score\": %d, %s\"output\": \"", k + 1, t->score,
                t->result == SKIPPED ? 0 : t->points, status);
        put_escaped(f, t->result == SKIPPED ? "skipped: the data it needs is absent\n" : "", 0);
        put_escaped(f, t->output, 0);
        fputs("\"}", f);
    }
    fputs("\n  ]\n}\n", f);
    return fclose(f) != 0;
}

static int write_junit(const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return 1;
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n", f);
    for (size_t first = 0; first < n_results;) {
        size_t last = first;
        int failures = 0, skipped = 0;
        while (last < n_results && strcmp(results[last].chapter, results[first].chapter) == 0) {
            failures += results[last].result == FAILED;
            skipped += results[last].result == SKIPPED;
            last++;
        }
        fputs("  <testsuite name=\"", f);
        put_escaped(f, results[first].chapter, 1);
        fprintf(f, "\" tests=\"%zu\" failures=\"%d\" errors=\"0\" skipped=\"%d\">\n", last - first, failures,
                skipped);
        for (size_t k = first; k < last; k++) {
            const test_result *t = &results[k];
            fputs("    <testcase classname=\"", f);
            put_escaped(f, t->chapter, 1);
            fputs("\" name=\"", f);
            put_escaped(f, t->name, 1);
            fprintf(f, "\">\n      <properties><property name=\"points\" value=\"%d\"/>"
                       "<property name=\"score\" value=\"%d\"/></properties>\n",
                    t->points, t->score);
            if (t->result == FAILED)
                fprintf(f, "      <failure message=\"lost %d point%s\">", t->points, t->points == 1 ? "" : "s");
            else if (t->result == SKIPPED)
                fputs("      <skipped/>\n      <system-out>", f);
            else
                fputs("      <system-out>", f);
            put_escaped(f, t->output, 1);
            fputs(t->result == FAILED ? "</failure>\n" : "</system-out>\n", f);
            fputs("    </testcase>\n", f);
        }
        fputs("  </testsuite>\n", f);
        first = last;
    }
    fputs("</testsuites>\n", f);
    return fclose(f) != 0;
}

static int usage(void)
{
    fprintf(stderr, "usage: grade [--timeout SECONDS] [--budget SECONDS] [--memory MB] [--json FILE] [--junit FILE] "
                    "[--notes FILE] [--user NAME] [--require-full] "
                    "CHAPTER SUITE REFERENCE BUILDLOG FLOAT FLOATLOG FLOATREFERENCE ...\n");
    return 1;
}

/* Copies the executable src into the sandbox, owned by root, runnable by
 * everyone, writable by nobody else; returns the copy's path. */
static char *sandbox_copy(const char *src, int k)
{
    buffer path = {0};
    char name[32];
    snprintf(name, sizeof name, "/suite-%d", k);
    buf_str(&path, sandbox);
    buf_str(&path, name);
    int in = open(src, O_RDONLY), out = open(path.s, O_WRONLY | O_CREAT | O_EXCL, 0755);
    char chunk[65536];
    ssize_t n = 0;
    while (in >= 0 && out >= 0 && (n = read(in, chunk, sizeof chunk)) > 0)
        if (write(out, chunk, (size_t)n) != n) {
            n = -1;
            break;
        }
    if (in < 0 || out < 0 || n < 0 || fchmod(out, 0755) != 0) {
        fprintf(stderr, "grade: cannot copy %s into %s\n", src, sandbox);
        exit(1);
    }
    close(in);
    close(out);
    return path.s;
}

/* Removes the sandbox and what the tests left in it. */
static void remove_sandbox(void)
{
    if (!*sandbox)
        return;
    if (as_user && !kill_user_processes()) { /* its run folders are the user's: none of theirs may live */
        fprintf(stderr, "grade: processes of the tests' user outlived the clean-up; %s was left, not removed\n",
                sandbox);
        return;
    }
    scratch_remove(sandbox);
}

/* The sandbox: a folder of /tmp for the suites' copies and the runs'
 * folders, which the tests' user may enter but not change. */
static void make_sandbox(void)
{
    snprintf(sandbox, sizeof sandbox, "/tmp/rt-grade-XXXXXX");
    if (!mkdtemp(sandbox) || chmod(sandbox, 0711) != 0) {
        fprintf(stderr, "grade: cannot make a folder under /tmp\n");
        exit(1);
    }
}

/* --user: the user the tests run as, with nothing of it running before. */
static void become_ready(const char *user)
{
    struct passwd *pw = getpwnam(user);
    if (!pw) {
        fprintf(stderr, "grade: no user '%s' (the autograder's setup.sh creates it)\n", user);
        exit(1);
    }
    if (geteuid() != 0 || pw->pw_uid == 0) {
        fprintf(stderr, "grade: --user needs root, and a user other than root\n");
        exit(1);
    }
    as_user = 1;
    user_uid = pw->pw_uid;
    user_gid = pw->pw_gid;
    if (!kill_user_processes()) { /* nothing of that user runs before the tests */
        fprintf(stderr, "grade: processes of %s still run and cannot be stopped\n", user);
        exit(1);
    }
    scratch_remove_owned(user_uid);
}

/* path from the root (it must exist), or the grader stops. */
static const char *absolute(const char *path)
{
    char *full = realpath(path, NULL);
    if (!full) {
        fprintf(stderr, "grade: %s: %s\n", path, strerror(errno));
        exit(1);
    }
    return full;
}

/* A positive number of an option, or -1. */
static double number(const char *text, double max)
{
    char *end;
    double x = strtod(text, &end);
    return *end || !(x > 0 && x <= max) ? -1 : x;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--clean") == 0) { /* what the Makefile shows of a submission's */
        const char *text = read_file("/dev/stdin");      /* its NUL bytes made '?' */
        print_clean(text, strlen(text));
        return fflush(stdout) != 0;
    }
    double timeout = 10, budget = 3600;
    const char *json = NULL, *junit = NULL, *notes = NULL, *user = NULL;
    int require_full = 0, k = 1;
    for (; k < argc && strncmp(argv[k], "--", 2) == 0; k++) {
        if (strcmp(argv[k], "--timeout") == 0 && k + 1 < argc) {
            if ((timeout = number(argv[++k], 86400)) < 0)
                return usage();
        } else if (strcmp(argv[k], "--budget") == 0 && k + 1 < argc) {
            if ((budget = number(argv[++k], 1e6)) < 0)
                return usage();
        } else if (strcmp(argv[k], "--memory") == 0 && k + 1 < argc) {
            double mb = number(argv[++k], 1 << 20);
            if (mb < 0)
                return usage();
            memory_mb = (long)mb;
        } else if (strcmp(argv[k], "--json") == 0 && k + 1 < argc) {
            json = argv[++k];
        } else if (strcmp(argv[k], "--junit") == 0 && k + 1 < argc) {
            junit = argv[++k];
        } else if (strcmp(argv[k], "--notes") == 0 && k + 1 < argc) {
            notes = argv[++k];
        } else if (strcmp(argv[k], "--user") == 0 && k + 1 < argc) {
            user = argv[++k];
        } else if (strcmp(argv[k], "--require-full") == 0) {
            require_full = 1;
        } else {
            return usage();
        }
    }
    if ((argc - k) % 7 != 0)
        return usage();
    budget_end = now() + budget;
    signal(SIGPIPE, SIG_IGN);
    if (notes) {
        char *text = read_file(notes);
        buf_str(&summary, text);
        free(text);
    }
    if (user) {
        become_ready(user);
        prctl(PR_SET_CHILD_SUBREAPER, 1); /* the tests' orphans come to the grader, which reaps them */
    }
    make_sandbox();
    int copies = 0;
    for (; k < argc; k += 7) {
        chapter_files c = {argv[k], argv[k + 1], argv[k + 2], argv[k + 3], argv[k + 4], argv[k + 5], argv[k + 6]};
        c.reference = absolute(c.reference); /* a run's working folder is its own */
        if (strcmp(c.float_reference, "-") != 0)
            c.float_reference = absolute(c.float_reference);
        if (as_user) { /* the user cannot read the originals; the references stay where it cannot run them */
            if (access(c.suite, X_OK) == 0)
                c.suite = sandbox_copy(c.suite, copies++);
            if (strcmp(c.float_suite, "-") != 0 && access(c.float_suite, X_OK) == 0)
                c.float_suite = sandbox_copy(c.float_suite, copies++);
        }
        if (grade_chapter(&c, timeout) != 0) {
            remove_sandbox();
            return 1;
        }
    }
    remove_sandbox();
    if (budget_left() < 1)
        printf("the grading's time budget (%g s) was used up: the tests not run count as failed\n", budget);

    /* The table: one line per chapter, then the total. */
    int score = 0, max_score = 0, passed = 0, counted = 0;
    printf("\n%-24s %8s %8s\n", "chapter", "tests", "points");
    for (size_t first = 0; first < n_results;) {
        int s = 0, m = 0, p = 0, c = 0;
        size_t last = first;
        for (; last < n_results && strcmp(results[last].chapter, results[first].chapter) == 0; last++) {
            if (results[last].result == SKIPPED || results[last].info)
                continue;
            s += results[last].score;
            m += results[last].points;
            p += results[last].result == PASSED;
            c++;
        }
        char tests[32], points[32];
        snprintf(tests, sizeof tests, "%d/%d", p, c);
        snprintf(points, sizeof points, "%d/%d", s, m);
        printf("%-24s %8s %8s\n", results[first].chapter, tests, points);
        score += s;
        max_score += m;
        passed += p;
        counted += c;
        first = last;
    }
    char tests[32], points[32];
    snprintf(tests, sizeof tests, "%d/%d", passed, counted);
    snprintf(points, sizeof points, "%d/%d", score, max_score);
    printf("%-24s %8s %8s\n", "total", tests, points);
    if (n_results == 0) {
        printf("nothing to grade: none of these chapters has a test\n");
        return 1;
    }

    if (json && write_json(json, score, max_score) != 0) {
        fprintf(stderr, "grade: cannot write %s\n", json);
        return 1;
    }
    if (junit && write_junit(junit) != 0) {
        fprintf(stderr, "grade: cannot write %s\n", junit);
        return 1;
    }
    if (require_full && (score != max_score || float_failures)) {
        printf("expected full marks: %d of %d points lost, %d tests fail in the float build\n", max_score - score,
               max_score, float_failures);
        return 1;
    }
    return 0;
}
