#include "answers.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

static int answers_fd = -1;

void answers_open(int fd)
{
    answers_fd = fd;
    answers_record("eps %a", (double)REAL_EPSILON);
}

void answers_end(int failed)
{
    answers_record("end %d", failed);
    answers_fd = -1;
}

void answers_record(const char *format, ...)
{
    if (answers_fd < 0)
        return;
    char line[512];
    va_list args;
    va_start(args, format);
    int n = vsnprintf(line, sizeof line - 1, format, args);
    va_end(args);
    if (n < 0)
        return;
    if ((size_t)n > sizeof line - 2)
        n = (int)sizeof line - 2;
    line[n++] = '\n';
    for (int done = 0; done < n;) { /* a pipe: whole lines, in order */
        ssize_t w = write(answers_fd, line + done, (size_t)(n - done));
        if (w <= 0)
            return;
        done += (int)w;
    }
}

/* Spaces and newlines of `what` would break the record's last field: '_'. */
static void record_answer(const char *what, double value, double tolerance)
{
    char clean[300];
    snprintf(clean, sizeof clean, "%s", what);
    for (char *c = clean; *c; c++)
        if (*c == '\n' || *c == '\r')
            *c = ' ';
    answers_record("answer %a %a %s", value, tolerance, clean);
}

void suite_answer(const char *what, double value, double tolerance) { record_answer(what, value, tolerance); }

/* Three answers, what.n[0], what.n[1], what.n[2]. */
static void answer_three(const char *what, const char n[3], const double v[3], double tolerance)
{
    for (int k = 0; k < 3; k++) {
        char name[300];
        snprintf(name, sizeof name, "%s.%c", what, n[k]);
        record_answer(name, v[k], tolerance);
    }
}

void suite_answer_vec3(const char *what, vec3 value, double tolerance)
{
    answer_three(what, "xyz", (const double[3]){value.x, value.y, value.z}, tolerance);
}

void suite_answer_rgb(const char *what, color value, double tolerance)
{
    answer_three(what, "rgb", (const double[3]){value.r, value.g, value.b}, tolerance);
}

extern const seeded_check suite_seeded_checks[] __attribute__((weak));

const seeded_check *seeded_all(void) { return suite_seeded_checks; }

const seeded_check *seeded_for(const char *name)
{
    if (!suite_seeded_checks)
        return NULL;
    for (const seeded_check *c = suite_seeded_checks; c->test; c++)
        if (strcmp(c->test, name) == 0)
            return c;
    return NULL;
}

void suite_assert_true(LargestIntegralType holds, const char *expression, const char *file, int line)
{
    answers_record("true %d", holds != 0);
    _assert_true(holds, expression, file, line);
}

void suite_assert_int(LargestIntegralType a, LargestIntegralType b, int equal, const char *file, int line)
{
    if (equal) {
        answers_record("int %llu %llu", (unsigned long long)a, (unsigned long long)b);
        _assert_int_equal(a, b, file, line);
    } else {
        answers_record("true %d", a != b);
        _assert_int_not_equal(a, b, file, line);
    }
}

void suite_assert_string(const char *a, const char *b, const char *file, int line)
{
    answers_record("true %d", a && b && strcmp(a, b) == 0);
    _assert_string_equal(a, b, file, line);
}

void suite_assert_memory(const void *a, const void *b, size_t size, int equal, const char *file, int line)
{
    answers_record("true %d", (memcmp(a, b, size) == 0) == (equal != 0));
    if (equal)
        _assert_memory_equal(a, b, size, file, line);
    else
        _assert_memory_not_equal(a, b, size, file, line);
}

void suite_fail(const char *file, int line)
{
    answers_record("fail");
    _fail(file, line);
}

void suite_skip(const char *file, int line)
{
    answers_record("skip");
    _skip(file, line);
}
