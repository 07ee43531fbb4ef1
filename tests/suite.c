#include "suite.h"

#include "exercise.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void check_close(double expected, double actual, double tolerance, const char *what, const char *file, int line)
{
    answers_record("close %a %a %a", expected, actual, tolerance);
    double error = actual - expected;
    if (!(error <= tolerance && -error <= tolerance)) { /* also fails on NaN */
        print_error("%s = %.17g, expected %.17g within %.3g (off by %.3g)\n", what, actual, expected, tolerance,
                    error);
        _fail(file, line);
    }
}

/* The records of a vec3 check: one a component (answers.h). */
static void record_vec3(const double e[3], const double a[3], double tolerance)
{
    for (int k = 0; k < 3; k++)
        answers_record("close %a %a %a", e[k], a[k], tolerance);
}

void check_vec3_close(vec3 expected, vec3 actual, double tolerance, const char *what, const char *file, int line)
{
    const double e[3] = {expected.x, expected.y, expected.z}, a[3] = {actual.x, actual.y, actual.z};
    record_vec3(e, a, tolerance);
    for (int k = 0; k < 3; k++) {
        double error = a[k] - e[k];
        if (!(error <= tolerance && -error <= tolerance)) {
            print_error("%s = (%.17g, %.17g, %.17g), expected (%.17g, %.17g, %.17g) within %.3g per component\n",
                        what, a[0], a[1], a[2], e[0], e[1], e[2], tolerance);
            _fail(file, line);
        }
    }
}

const char *describe(const char *format, ...)
{
    static char buffers[8][600];
    static int next;
    char *out = buffers[next++ % 8];
    va_list args;
    va_start(args, format);
    vsnprintf(out, sizeof buffers[0], format, args);
    va_end(args);
    return out;
}

/* A suspect matches when it is as close to the got value as the expected
 * value had to be, or within a few roundings of its own size. */
static int near(double a, double b, double tolerance)
{
    double slack = fmax(4 * tolerance, 64 * (double)REAL_EPSILON * fmax(1, fmax(fabs(a), fabs(b))));
    return fabs(a - b) <= slack || (a != a && b != b);
}

/* What a failed check says instead of a guess when the placeholder of an
 * unfinished exercise ran in the test. */
static const char placeholder_ran[] = "    likely mistake: none yet: the placeholder of an unfinished exercise ran in "
                                      "this test (the line 'is still an exercise' names it); finish it first\n";

/* The "likely mistake" lines of a failed check: when a placeholder ran in
 * this test (an untouched exercise), that, and no guess; else every suspect
 * that matched (mistakes that give the same numbers are all named), or the
 * hint when none did. */
static void print_why(const char *hint, const char *const *matched, size_t n_matched)
{
    if (atomic_load(&exercise_stub_ran)) {
        print_error("%s", placeholder_ran);
        return;
    }
    if (n_matched == 0) {
        print_error("    likely mistake: %s\n", hint);
        return;
    }
    for (size_t k = 0; k < n_matched; k++)
        print_error("    %s %s\n", k == 0 ? "likely mistake:" : "or, the same numbers:", matched[k]);
}

void suite_fail_msg(const char *file, int line, const char *format, ...)
{
    char message[4096];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    char *guess = strstr(message, "\n    likely mistake: ");
    if (guess && atomic_load(&exercise_stub_ran)) {
        *guess = '\0';
        print_error("ERROR: %s\n%s", message, placeholder_ran);
    } else {
        print_error("ERROR: %s\n", message);
    }
    _fail(file, line);
}

void check_close_why(double expected, double actual, double tolerance, const char *input, const char *hint,
                     const suspect *suspects, size_t n, const char *file, int line)
{
    answers_record("close %a %a %a", expected, actual, tolerance);
    double error = actual - expected;
    if (error <= tolerance && -error <= tolerance)
        return;
    const char *matched[SUITE_MAX_SUSPECTS];
    size_t n_matched = 0;
    for (size_t k = 0; k < n && n_matched < SUITE_MAX_SUSPECTS; k++)
        if (near(suspects[k].value, actual, tolerance))
            matched[n_matched++] = suspects[k].mistake;
    print_error("%s\n    expected %.17g (within %.3g)\n    got      %.17g\n", input, expected, tolerance, actual);
    print_why(hint, matched, n_matched);
    _fail(file, line);
}

void check_vec3_why(vec3 expected, vec3 actual, double tolerance, const char *input, const char *hint,
                    const suspect_vec3 *suspects, size_t n, const char *file, int line)
{
    const double e[3] = {expected.x, expected.y, expected.z}, a[3] = {actual.x, actual.y, actual.z};
    record_vec3(e, a, tolerance);
    int ok = 1;
    for (int k = 0; k < 3; k++)
        ok &= a[k] - e[k] <= tolerance && e[k] - a[k] <= tolerance;
    if (ok)
        return;
    const char *matched[SUITE_MAX_SUSPECTS];
    size_t n_matched = 0;
    for (size_t k = 0; k < n && n_matched < SUITE_MAX_SUSPECTS; k++) {
        const vec3 s = suspects[k].value;
        if (near(s.x, actual.x, tolerance) && near(s.y, actual.y, tolerance) && near(s.z, actual.z, tolerance))
            matched[n_matched++] = suspects[k].mistake;
    }
    print_error("%s\n    expected (%.17g, %.17g, %.17g) (within %.3g per component)\n"
                "    got      (%.17g, %.17g, %.17g)\n",
                input, e[0], e[1], e[2], tolerance, a[0], a[1], a[2]);
    print_why(hint, matched, n_matched);
    _fail(file, line);
}

double suite_uniform(unsigned long *state)
{
    *state = *state * 6364136223846793005UL + 1442695040888963407UL;
    return (double)((*state >> 11) & ((1UL << 53) - 1)) / (double)(1UL << 53);
}

vec3 suite_random_unit(unsigned long *state)
{
    for (;;) {
        double x = 2 * suite_uniform(state) - 1; /* one after the other: arguments have no order */
        double y = 2 * suite_uniform(state) - 1;
        double z = 2 * suite_uniform(state) - 1;
        vec3 v = vec3_make((real)x, (real)y, (real)z);
        real l = vec3_length(v);
        if (l > (real)0.1 && l <= 1)
            return vec3_scale(v, 1 / l);
    }
}

const char *cornell_data(void)
{
    static const char *const candidates[] = {"../shared/cornell/sp17-ray1/data", NULL};
    const char *env = getenv("RT_CORNELL");
    struct stat st;
    if (env) {
        if (stat(env, &st) == 0 && S_ISDIR(st.st_mode))
            return env;
        fail_msg("RT_CORNELL=%s is not a folder", env);
    }
    for (int k = 0; candidates[k]; k++)
        if (stat(candidates[k], &st) == 0 && S_ISDIR(st.st_mode))
            return candidates[k];
    if (getenv("RT_REQUIRE_CORNELL"))
        fail_msg("RT_REQUIRE_CORNELL is set but the Cornell corpus is not at %s", candidates[0]);
    static bool said; /* once per suite: why its tests of the course's scenes skip */
    if (!said)
        printf("note: the course's scenes are not at %s (run from the top of the copy, or set RT_CORNELL to "
               "their folder): the tests that read them skip\n", candidates[0]);
    said = true;
    return NULL;
}

static int forget_stubs(void **state)
{
    (void)state;
    atomic_store(&exercise_stub_ran, false);
    return 0;
}

struct seeded_state {
    const seeded_check *check;
    unsigned long seed;
};

static void run_seeded(void **state)
{
    struct seeded_state *run = *state;
    unsigned long rng = run->seed;
    run->check->check(&rng);
}

int suite_main(const char *name, const graded_test *tests, size_t n, int argc, char **argv)
{
    struct CMUnitTest *plain = calloc(n + 1, sizeof *plain); /* and a seeded check */
    if (!plain)
        return 1;
    size_t count = 0;
    const char *only = NULL;
    if (argc == 2 && strcmp(argv[1], "--seeded") == 0) { /* the tests named by tests/seeded/ (check-seeded.sh) */
        for (const seeded_check *c = seeded_all(); c && c->test; c++)
            printf("%s\n", c->test);
        free(plain);
        return 0;
    }
    if (argc == 2 && strcmp(argv[1], "--list") == 0) {
        for (size_t k = 0; k < n; k++)
            printf("%s %d\n", tests[k].test.name, tests[k].points);
        free(plain);
        return 0;
    }
    /* --answers FD --seed SEED (tools/grade): the checks write what they
     * compare on FD, and the test's check of inputs drawn from SEED runs
     * after it (answers.h). */
    int answers = -1;
    unsigned long seed = 0;
    if (argc == 7 && strcmp(argv[3], "--answers") == 0 && strcmp(argv[5], "--seed") == 0) {
        char *end;
        answers = (int)strtol(argv[4], &end, 10);
        seed = strtoul(argv[6], &end, 16);
        argc = 3;
    }
    if (argc == 3 && strcmp(argv[1], "--only") == 0)
        only = argv[2];
    else if (argc != 1) {
        fprintf(stderr, "usage: %s [--list | --only TEST [--answers FD --seed HEX]]\n", argv[0]);
        free(plain);
        return 2;
    }
    for (size_t k = 0; k < n; k++)
        if (!only || strcmp(tests[k].test.name, only) == 0) {
            plain[count] = tests[k].test;
            if (!plain[count].setup_func) /* each test starts with no placeholder run */
                plain[count].setup_func = forget_stubs;
            count++;
        }
    if (only && count == 0) {
        fprintf(stderr, "%s: no test named '%s' (see --list)\n", argv[0], only);
        free(plain);
        return 2;
    }
    const seeded_check *seeded = answers >= 0 ? seeded_for(only) : NULL;
    if (seeded) { /* the seeded check: one more test, given its check and the seed */
        static struct seeded_state run;
        run = (struct seeded_state){seeded, seed};
        plain[count++] = (struct CMUnitTest){.name = "answers to inputs drawn at grading time (the grader judges them)",
                                             .test_func = run_seeded, .initial_state = &run};
    }
    if (answers >= 0)
        answers_open(answers);
    int failed = _cmocka_run_group_tests(name, plain, count, NULL, NULL);
    free(plain);
    if (answers >= 0) {
        fflush(NULL);
        answers_end(failed);
    }
    return failed;
}
