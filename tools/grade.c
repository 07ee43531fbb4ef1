/* grade.c - run each graded test in its own process and report the points.
 *
 *     grade [--timeout SECONDS] [--json FILE] [--junit FILE] [--notes FILE]
 *           [--user NAME] [--require-full]
 *           CHAPTER SUITE REFERENCE BUILDLOG FLOAT FLOATLOG ...
 *
 * Six words per chapter: the chapter's name; SUITE, the test binary built
 * with the student's files of that chapter (missing when they did not
 * compile); REFERENCE, the same suite built from the reference, which lists
 * the tests and their points (`--list`); BUILDLOG, the compiler's messages
 * (shown: warnings do not cost points, errors fail the chapter); FLOAT and
 * FLOATLOG, the student's suite of the float build (REAL=float) and its
 * messages, or "-" "-".
 *
 * Every test runs as `SUITE --only NAME --report 3` in a child process of its
 * own, with its output captured and a time limit: a test that crashes, hangs
 * or exits early fails alone.  A test passes when the child exits with
 * status 0 and the suite wrote back, on descriptor 3, the random token the
 * grader gave it with 0 failures: printing what cmocka prints, or calling
 * exit(0) from the tested code, does not pass.  A skipped test (the Cornell
 * corpus is absent) counts neither way.  The float build runs each test
 * again; its verdict is reported with the test and in one line per chapter
 * worth no points (with --require-full it must pass too).
 *
 * --user NAME (as root; the autograder) runs the tests as that user: the
 * suites are copied into a fresh folder under /tmp that the user can run but
 * not change, the working folder and HOME are a scratch folder of the user's,
 * the environment is emptied but for PATH, HOME, TMPDIR and LANG, and after
 * every test every process of that user is killed, so nothing it started
 * (even in a session or process group of its own) outlives its test.
 *
 * Writes a score table to stdout, a Gradescope results.json (--json; the
 * --notes file and the compiler's messages are its "output") and a JUnit XML
 * report (--junit).  Exits 0 when grading ran, 1 on a usage or I/O problem
 * or when there was nothing to grade, and with --require-full also 1 when
 * any point was lost.
 */
#define _DEFAULT_SOURCE /* setgroups */
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pwd.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

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

/* The user the tests run as (--user), and its folders. */
static int as_user;
static uid_t user_uid;
static gid_t user_gid;
static char sandbox[64], workdir[96];
static char *user_env[5];

enum { REPORT_FD = 3 }; /* where a suite reads its token and writes its verdict */

/* A token nobody can guess: 32 hex digits from /dev/urandom. */
static void make_token(char token[33])
{
    unsigned char bytes[16] = {0};
    int fd = open("/dev/urandom", O_RDONLY);
    if (fd < 0 || read(fd, bytes, sizeof bytes) != (ssize_t)sizeof bytes) {
        fprintf(stderr, "grade: cannot read /dev/urandom\n");
        exit(1);
    }
    close(fd);
    for (int k = 0; k < 16; k++)
        snprintf(token + 2 * k, 3, "%02x", bytes[k]);
}

/* Kills every process of the tests' user: a child that becomes that user
 * sends SIGKILL to every process it may signal (kill(-1)), which are exactly
 * that user's processes, whatever session or process group they moved to. */
static void kill_user_processes(void)
{
    for (int round = 0; round < 2; round++) {
        pid_t pid = fork();
        if (pid == 0) {
            if (setgid(user_gid) == 0 && setuid(user_uid) == 0)
                kill(-1, SIGKILL);
            _exit(0);
        }
        if (pid > 0)
            waitpid(pid, NULL, 0);
    }
}

/* Runs argv with stdin from /dev/null and stdout+stderr captured (the first
 * OUTPUT_LIMIT bytes), in its own process group, killed after `timeout`
 * seconds; as the tests' user when `untrusted` and --user was given.  With a
 * token, the child gets descriptor REPORT_FD, a socket that holds the token,
 * and what it writes back there goes to *report.  Returns the wait status, or
 * -1 when it timed out (or could not be started: then the reason is in the
 * output). */
static int run(char *const argv[], double timeout, buffer *out, int untrusted, const char *token, buffer *report)
{
    int fds[2], sv[2] = {-1, -1};
    if (pipe(fds) != 0) {
        buf_str(out, "grade: pipe failed\n");
        return -1;
    }
    if (token && socketpair(AF_UNIX, SOCK_STREAM, 0, sv) != 0) {
        close(fds[0]);
        close(fds[1]);
        buf_str(out, "grade: socketpair failed\n");
        return -1;
    }
    if (token) { /* the token waits in the socket for the suite to read it */
        char line[40];
        int n = snprintf(line, sizeof line, "%s\n", token);
        if (write(sv[0], line, (size_t)n) != n)
            buf_str(out, "grade: cannot pass the token\n");
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        if (token) {
            close(sv[0]);
            close(sv[1]);
        }
        buf_str(out, "grade: fork failed\n");
        return -1;
    }
    if (pid == 0) {
        setpgid(0, 0);
        int null = open("/dev/null", O_RDONLY);
        if (null >= 0)
            dup2(null, STDIN_FILENO);
        dup2(fds[1], STDOUT_FILENO);
        dup2(fds[1], STDERR_FILENO);
        if (token)
            dup2(sv[1], REPORT_FD);
        for (int fd = token ? REPORT_FD + 1 : REPORT_FD; fd < 1024; fd++)
            close(fd); /* nothing of the grader's stays open */
        struct rlimit no_core = {0, 0};
        setrlimit(RLIMIT_CORE, &no_core);
        if (untrusted && as_user) {
            struct rlimit procs = {256, 256}, file = {1 << 28, 1 << 28};
            setrlimit(RLIMIT_NPROC, &procs); /* threads count too */
            setrlimit(RLIMIT_FSIZE, &file);
            if (chdir(workdir) != 0 || setgroups(0, NULL) != 0 || setgid(user_gid) != 0 || setuid(user_uid) != 0 ||
                setuid(0) == 0) {
                fprintf(stderr, "grade: cannot become the tests' user\n");
                _exit(127);
            }
        } else {
            unsetenv("CMOCKA_MESSAGE_OUTPUT"); /* cmocka's plain report, which is parsed below */
            unsetenv("CMOCKA_XML_FILE");
        }
        alarm((unsigned)timeout + 2); /* a second guard, should the grader itself die */
        if (untrusted && as_user)
            execve(argv[0], argv, user_env);
        else
            execv(argv[0], argv);
        fprintf(stderr, "grade: cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    setpgid(pid, pid); /* also here, so that the kill below cannot miss */
    close(fds[1]);
    if (token)
        close(sv[1]);
    const double deadline = now() + timeout;
    int open_pipe = 1, status = 0, timed_out = 0;
    pid_t done = 0;
    while (!done) {
        double left = deadline - now();
        if (left <= 0) {
            timed_out = 1;
            break;
        }
        if (open_pipe) {
            struct pollfd p = {fds[0], POLLIN, 0};
            /* A short wait, so that an exit is seen even while something the
             * test started still holds the pipe open. */
            int ready = poll(&p, 1, left < 0.05 ? (int)(left * 1000) + 1 : 50);
            if (ready > 0) {
                char chunk[4096];
                ssize_t n = read(fds[0], chunk, sizeof chunk);
                if (n > 0) {
                    size_t keep = out->len < OUTPUT_LIMIT ? OUTPUT_LIMIT - out->len : 0;
                    if ((size_t)n > keep)
                        out->truncated = 1;
                    buf_add(out, chunk, (size_t)n < keep ? (size_t)n : keep);
                } else if (n == 0 || errno != EINTR) {
                    open_pipe = 0;
                }
            }
        } else {
            struct timespec pause = {0, 5 * 1000 * 1000};
            nanosleep(&pause, NULL);
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
    } else if (open_pipe) { /* exited: read what is left, without waiting for any stray grandchild */
        fcntl(fds[0], F_SETFL, O_NONBLOCK);
        char chunk[4096];
        ssize_t n;
        while ((n = read(fds[0], chunk, sizeof chunk)) > 0) {
            size_t keep = out->len < OUTPUT_LIMIT ? OUTPUT_LIMIT - out->len : 0;
            buf_add(out, chunk, (size_t)n < keep ? (size_t)n : keep);
        }
        kill(-pid, SIGKILL); /* anything the test left running */
    }
    if (untrusted && as_user)
        kill_user_processes(); /* also what left the process group */
    close(fds[0]);
    if (token) { /* what the suite wrote back; the child and all it started are gone */
        fcntl(sv[0], F_SETFL, O_NONBLOCK);
        char chunk[256];
        ssize_t n;
        while (report->len < 4096 && (n = read(sv[0], chunk, sizeof chunk)) > 0)
            buf_add(report, chunk, (size_t)n);
        close(sv[0]);
    }
    if (out->truncated)
        buf_str(out, "\n[output truncated]\n");
    return timed_out ? -1 : status;
}

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
            buf_add(&b, chunk, n);
        fclose(f);
    }
    return buf_take(&b);
}

/* Prints the lines of a failed test's output that say why (the test's
 * messages, cmocka's ERROR and LINE lines, the grader's note), at most five. */
static void print_reason(const char *output)
{
    int shown = 0;
    for (const char *line = output; *line && shown < 5;) {
        const char *end = strchr(line, '\n');
        size_t n = end ? (size_t)(end - line) : strlen(line);
        static const char *const framing[] = {"[==", "[ RUN", "[       OK", "[  FAILED", "[  PASSED", "[  SKIPPED",
                                              " 1 FAILED TEST", NULL};
        int show = n > 0;
        for (int k = 0; show && framing[k]; k++)
            show = strncmp(line, framing[k], strlen(framing[k])) != 0;
        if (show) {
            printf("        %.*s\n", (int)(n > 200 ? 200 : n), line);
            shown++;
        }
        line += n + (end != NULL);
    }
}

/* The results' "output": the --notes file, then the compiler's messages. */
static buffer summary;
static int float_failures; /* tests that failed in the float build */

/* Runs test `name` of `suite`; the verdict, with what it printed and the grader's note in *out. */
static verdict run_test(const char *suite, const char *name, double timeout, buffer *out)
{
    char token[33];
    make_token(token);
    char report_fd[8];
    snprintf(report_fd, sizeof report_fd, "%d", REPORT_FD);
    char *argv[] = {(char *)suite, "--only", (char *)name, "--report", report_fd, NULL};
    buffer report = {0};
    int status = run(argv, timeout, out, 1, token, &report);
    char expected[40];
    snprintf(expected, sizeof expected, "%s 0\n", token);
    char note[200] = "";
    verdict v = FAILED;
    if (status < 0)
        snprintf(note, sizeof note, "grade: timed out after %g s (an endless loop?)\n", timeout);
    else if (WIFSIGNALED(status))
        snprintf(note, sizeof note, "grade: crashed: %s (signal %d)\n", strsignal(WTERMSIG(status)),
                 WTERMSIG(status));
    else if (WEXITSTATUS(status) != 0)
        snprintf(note, sizeof note, "grade: failed (exit status %d)\n", WEXITSTATUS(status));
    else if (strcmp(buf_take(&report), expected) != 0)
        snprintf(note, sizeof note, "grade: the test exited before the suite reported it passed\n");
    else if (strstr(buf_take(out), "[  SKIPPED ]"))
        v = SKIPPED;
    else
        v = PASSED;
    buf_str(out, note);
    free(report.s);
    return v;
}

/* A file's text, "" when it is missing or empty. */
static char *log_text(const char *path) { return strcmp(path, "-") == 0 ? xstrdup("") : read_file(path); }

static int grade_chapter(const char *chapter, const char *suite, const char *reference, const char *buildlog,
                         const char *float_suite, const char *float_log, double timeout)
{
    buffer listing = {0};
    char *list_argv[] = {(char *)reference, "--list", NULL};
    int status = run(list_argv, timeout, &listing, 0, NULL, NULL);
    if (status < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "grade: %s --list failed:\n%s", reference, buf_take(&listing));
        return 1;
    }
    int built = access(suite, X_OK) == 0;
    int with_float = strcmp(float_suite, "-") != 0;
    int float_built = with_float && access(float_suite, X_OK) == 0;
    char *log = log_text(buildlog), *flog = log_text(float_log);
    printf("%s%s\n", chapter, built ? "" : ": the student's files do not compile; every test fails");
    if (built && *log) { /* warnings: shown, not counted */
        printf("  compiler messages (not counted):\n%s", log);
        buf_str(&summary, "\n");
        buf_str(&summary, chapter);
        buf_str(&summary, ": the compiler's messages for your files (warnings cost no points; fix them):\n");
        buf_str(&summary, log);
    }
    if (with_float && !float_built && built) {
        printf("  the float build (REAL=float) does not compile:\n%s", flog);
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
            buf_str(&out, "grade: the student's files did not compile:\n");
            buf_str(&out, log);
        } else {
            v = run_test(suite, name, timeout, &out);
        }
        if (with_float && v != SKIPPED) {
            buffer fout = {0};
            verdict fv = float_built ? run_test(float_suite, name, timeout, &fout) : FAILED;
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

/* Writes s as the body of a JSON string (or XML text when xml): control
 * characters escaped, bytes that are not UTF-8 replaced by '?'. */
static void put_escaped(FILE *f, const char *s, int xml)
{
    const unsigned char *p = (const unsigned char *)s;
    while (*p) {
        unsigned c = *p;
        int extra = c < 0x80 ? 0 : (c & 0xE0) == 0xC0 ? 1 : (c & 0xF0) == 0xE0 ? 2 : (c & 0xF8) == 0xF0 ? 3 : -1;
        if (extra > 0) { /* a multi-byte sequence: copied when well-formed */
            int ok = c >= 0xC2 && c <= 0xF4;
            for (int k = 1; ok && k <= extra; k++)
                ok = (p[k] & 0xC0) == 0x80;
            if (ok) {
                fwrite(p, 1, (size_t)extra + 1, f);
                p += extra + 1;
                continue;
            }
            extra = -1;
        }
        if (extra < 0) {
            fputc('?', f);
        } else if (xml) {
            switch (c) {
            case '&': fputs("&amp;", f); break;
            case '<': fputs("&lt;", f); break;
            case '>': fputs("&gt;", f); break;
            case '"': fputs("&quot;", f); break;
            case '\'': fputs("&apos;", f); break;
            default: fputc(c < 0x20 && c != '\t' && c != '\n' && c != '\r' ? '?' : (int)c, f);
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
    fprintf(stderr, "usage: grade [--timeout SECONDS] [--json FILE] [--junit FILE] [--notes FILE] [--user NAME] "
                    "[--require-full] CHAPTER SUITE REFERENCE BUILDLOG FLOAT FLOATLOG ...\n");
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
    pid_t pid = fork();
    if (pid == 0) {
        execlp("rm", "rm", "-rf", sandbox, (char *)NULL);
        _exit(127);
    }
    if (pid > 0)
        waitpid(pid, NULL, 0);
}

/* --user: the user, the sandbox folder, the scratch folder and the environment. */
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
    kill_user_processes(); /* nothing of that user runs before the tests */
    snprintf(sandbox, sizeof sandbox, "/tmp/rt-grade-XXXXXX");
    if (!mkdtemp(sandbox) || chmod(sandbox, 0711) != 0) {
        fprintf(stderr, "grade: cannot make a folder under /tmp\n");
        exit(1);
    }
    snprintf(workdir, sizeof workdir, "%s/work", sandbox);
    if (mkdir(workdir, 0700) != 0 || chown(workdir, user_uid, user_gid) != 0) {
        fprintf(stderr, "grade: cannot make %s\n", workdir);
        exit(1);
    }
    static char home[128];
    snprintf(home, sizeof home, "HOME=%s", workdir);
    user_env[0] = "PATH=/usr/bin:/bin";
    user_env[1] = home;
    user_env[2] = "TMPDIR=/tmp";
    user_env[3] = "LANG=C.UTF-8";
    user_env[4] = NULL;
}

int main(int argc, char **argv)
{
    double timeout = 10;
    const char *json = NULL, *junit = NULL, *notes = NULL, *user = NULL;
    int require_full = 0, k = 1;
    for (; k < argc && strncmp(argv[k], "--", 2) == 0; k++) {
        if (strcmp(argv[k], "--timeout") == 0 && k + 1 < argc) {
            char *end;
            timeout = strtod(argv[++k], &end);
            if (*end || !(timeout > 0 && timeout < 86400))
                return usage();
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
    if ((argc - k) % 6 != 0)
        return usage();
    signal(SIGPIPE, SIG_IGN);
    if (notes) {
        char *text = read_file(notes);
        buf_str(&summary, text);
        free(text);
    }
    if (user)
        become_ready(user);
    int copies = 0;
    for (; k < argc; k += 6) {
        char *suite = argv[k + 1], *float_suite = argv[k + 4];
        if (as_user && access(suite, X_OK) == 0)
            suite = sandbox_copy(suite, copies++);
        if (as_user && strcmp(float_suite, "-") != 0 && access(float_suite, X_OK) == 0)
            float_suite = sandbox_copy(float_suite, copies++);
        if (grade_chapter(argv[k], suite, argv[k + 2], argv[k + 3], float_suite, argv[k + 5], timeout) != 0) {
            remove_sandbox();
            return 1;
        }
    }
    remove_sandbox();

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
