/* grade.c - run each graded test in its own process and report the points.
 *
 *     grade [--timeout SECONDS] [--json FILE] [--junit FILE] [--require-full]
 *           CHAPTER SUITE REFERENCE BUILDLOG ...
 *
 * Four words per chapter: the chapter's name; SUITE, the test binary built
 * with the student's files of that chapter (missing when they did not
 * compile); REFERENCE, the same suite built from the solutions, which lists
 * the tests and their points (`--list`); BUILDLOG, the compiler's messages,
 * shown when SUITE is missing.
 *
 * Every test runs as `SUITE --only NAME` in a child process of its own, with
 * its output captured and a time limit: a test that crashes, hangs or exits
 * early fails alone.  A test passes when the child exits with status 0 and
 * cmocka reported it passed; a skipped test (the Cornell corpus is absent)
 * counts neither way.
 *
 * Writes a score table to stdout, a Gradescope results.json (--json) and a
 * JUnit XML report (--junit).  Exits 0 when grading ran, 1 on a usage or I/O
 * problem, and with --require-full also 1 when any point was lost.
 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

enum { OUTPUT_LIMIT = 16384 }; /* bytes of a test's output that are kept */

typedef enum { PASSED, FAILED, SKIPPED } verdict;

typedef struct {
    char *chapter, *name;
    int points, score;
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

/* Runs argv with stdin from /dev/null and stdout+stderr captured (the first
 * OUTPUT_LIMIT bytes), in its own process group, killed after `timeout`
 * seconds.  Returns the wait status, or -1 when it timed out (or could not
 * be started: then the reason is in the output). */
static int run(char *const argv[], double timeout, buffer *out)
{
    int fds[2];
    if (pipe(fds) != 0) {
        buf_str(out, "grade: pipe failed\n");
        return -1;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
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
        close(fds[0]);
        close(fds[1]);
        unsetenv("CMOCKA_MESSAGE_OUTPUT"); /* cmocka's plain report, which is parsed below */
        unsetenv("CMOCKA_XML_FILE");
        alarm((unsigned)timeout + 2); /* a second guard, should the grader itself die */
        execv(argv[0], argv);
        fprintf(stderr, "grade: cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    setpgid(pid, pid); /* also here, so that the kill below cannot miss */
    close(fds[1]);
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
            int ready = poll(&p, 1, (int)(left * 1000) + 1);
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
    close(fds[0]);
    if (out->truncated)
        buf_str(out, "\n[output truncated]\n");
    return timed_out ? -1 : status;
}

static void add_result(const char *chapter, const char *name, int points, verdict v, const char *output)
{
    if (n_results == cap_results) {
        cap_results = cap_results ? 2 * cap_results : 32;
        results = xrealloc(results, cap_results * sizeof *results);
    }
    results[n_results++] = (test_result){xstrdup(chapter), xstrdup(name), points, v == PASSED ? points : 0, v,
                                         xstrdup(output)};
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

static int grade_chapter(const char *chapter, const char *suite, const char *reference, const char *buildlog,
                         double timeout)
{
    buffer listing = {0};
    char *list_argv[] = {(char *)reference, "--list", NULL};
    int status = run(list_argv, timeout, &listing);
    if (status < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "grade: %s --list failed:\n%s", reference, buf_take(&listing));
        return 1;
    }
    int built = access(suite, X_OK) == 0;
    char *log = built ? NULL : read_file(buildlog);
    printf("%s%s\n", chapter, built ? "" : ": the student's files do not compile; every test fails");
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
            char *argv[] = {(char *)suite, "--only", name, NULL};
            status = run(argv, timeout, &out);
            char note[200] = "";
            if (status < 0)
                snprintf(note, sizeof note, "grade: timed out after %g s (an endless loop?)\n", timeout);
            else if (WIFSIGNALED(status))
                snprintf(note, sizeof note, "grade: crashed: %s (signal %d)\n", strsignal(WTERMSIG(status)),
                         WTERMSIG(status));
            else if (WEXITSTATUS(status) != 0)
                snprintf(note, sizeof note, "grade: failed (exit status %d)\n", WEXITSTATUS(status));
            else if (strstr(buf_take(&out), "[  SKIPPED ]"))
                v = SKIPPED;
            else if (strstr(buf_take(&out), "[  PASSED  ] 1 test(s)."))
                v = PASSED;
            else
                snprintf(note, sizeof note, "grade: the test exited before cmocka reported it passed\n");
            buf_str(&out, note);
        }
        add_result(chapter, name, points, v, buf_take(&out));
        printf("  %s  %-50s %3d/%d\n", v == PASSED ? "pass" : v == SKIPPED ? "skip" : "FAIL", name,
               v == PASSED ? points : 0, v == SKIPPED ? 0 : points);
        if (v == FAILED && built)
            print_reason(out.s);
        free(out.s);
    }
    free(log);
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
    fprintf(f, "{\n  \"score\": %d,\n  \"max_score\": %d,\n  \"tests\": [", score, max_score);
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
    fprintf(stderr, "usage: grade [--timeout SECONDS] [--json FILE] [--junit FILE] [--require-full] "
                    "CHAPTER SUITE REFERENCE BUILDLOG ...\n");
    return 1;
}

int main(int argc, char **argv)
{
    double timeout = 10;
    const char *json = NULL, *junit = NULL;
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
        } else if (strcmp(argv[k], "--require-full") == 0) {
            require_full = 1;
        } else {
            return usage();
        }
    }
    if ((argc - k) % 4 != 0)
        return usage();
    signal(SIGPIPE, SIG_IGN);
    for (; k < argc; k += 4)
        if (grade_chapter(argv[k], argv[k + 1], argv[k + 2], argv[k + 3], timeout) != 0)
            return 1;

    /* The table: one line per chapter, then the total. */
    int score = 0, max_score = 0, passed = 0, counted = 0;
    printf("\n%-24s %8s %8s\n", "chapter", "tests", "points");
    for (size_t first = 0; first < n_results;) {
        int s = 0, m = 0, p = 0, c = 0;
        size_t last = first;
        for (; last < n_results && strcmp(results[last].chapter, results[first].chapter) == 0; last++) {
            if (results[last].result == SKIPPED)
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
    if (n_results == 0)
        printf("(nothing to grade: none of these chapters has a test suite yet)\n");

    if (json && write_json(json, score, max_score) != 0) {
        fprintf(stderr, "grade: cannot write %s\n", json);
        return 1;
    }
    if (junit && write_junit(junit) != 0) {
        fprintf(stderr, "grade: cannot write %s\n", junit);
        return 1;
    }
    if (require_full && score != max_score) {
        printf("expected full marks: %d of %d points lost\n", max_score - score, max_score);
        return 1;
    }
    return 0;
}
