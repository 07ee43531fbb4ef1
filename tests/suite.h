/* suite.h - what every cmocka suite of the project shares.
 *
 * A suite declares its tests with the points each is worth (the grading
 * weights sit next to the tests) and ends with SUITE_MAIN:
 *
 *     static const graded_test tests[] = {
 *         GRADED(test_centre_ray, 2),
 *         GRADED(test_corner_rays, 3),
 *     };
 *     SUITE_MAIN("01_camera_rays", tests)
 *
 * The binary runs all its tests; `--list` prints "name points" a line,
 * `--seeded` the tests that check inputs drawn at grading time, and
 * `--only NAME` runs one test, which is how grading isolates each test.
 * `--only NAME --answers FD --seed SEED` (tools/grade) also writes what each
 * check compares on FD and runs the test's check of inputs drawn from SEED
 * (answers.h): the grader decides from that, never from what the process
 * that ran the student's code says.
 *
 * Debian's cmocka 1.1.5 has no assert for doubles with a tolerance:
 * assert_close() prints the expected and actual values and the tolerance.
 */
#ifndef RT_TESTS_SUITE_H
#define RT_TESTS_SUITE_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "answers.h"
#include "vec3.h"

typedef struct {
    struct CMUnitTest test;
    int points;
} graded_test;

#define GRADED(function, points) {cmocka_unit_test(function), (points)}

int suite_main(const char *name, const graded_test *tests, size_t n, int argc, char **argv);

#define SUITE_MAIN(name, tests)                                                                                    \
    int main(int argc, char **argv) { return suite_main(name, tests, sizeof(tests) / sizeof((tests)[0]), argc, argv); }

/* |actual - expected| <= tolerance, or the test fails printing all three. */
#define assert_close(expected, actual, tolerance)                                                                  \
    check_close((double)(expected), (double)(actual), (double)(tolerance), #actual, __FILE__, __LINE__)
void check_close(double expected, double actual, double tolerance, const char *what, const char *file, int line);

/* Each component within tolerance. */
#define assert_vec3_close(expected, actual, tolerance)                                                             \
    check_vec3_close((expected), (actual), (double)(tolerance), #actual, __FILE__, __LINE__)
void check_vec3_close(vec3 expected, vec3 actual, double tolerance, const char *what, const char *file, int line);

/* A likely mistake and the value it would give. */
typedef struct {
    double value;
    const char *mistake;
} suspect;
typedef struct {
    vec3 value;
    const char *mistake;
} suspect_vec3;

/* Like assert_close and assert_vec3_close, for a student's function: on
 * failure the message names the input (a string), the expected value, the
 * value got, and the likely mistake: every suspect whose value the got value
 * matches (two mistakes that give the same numbers are both named, up to
 * SUITE_MAX_SUSPECTS), else `hint`.  n suspects (0 and NULL for none).  When
 * the placeholder of an unfinished exercise ran in the test (EXERCISE_STUB,
 * exercise.h), it says that instead of guessing at a mistake. */
#define SUITE_MAX_SUSPECTS 8

/* cmocka's fail_msg, with the same rule for a message's "likely mistake:"
 * line: when a placeholder ran in the test, the rest of the message from
 * that line on is replaced by what assert_close_why says then. */
#undef fail_msg
#define fail_msg(...) suite_fail_msg(__FILE__, __LINE__, __VA_ARGS__)
void suite_fail_msg(const char *file, int line, const char *format, ...) CMOCKA_PRINTF_ATTRIBUTE(3, 4);
/* assert_true for a student's result, with fail_msg's message when it does
 * not hold: it writes assert_true's record for the grader ("true V", on a
 * pass too), so that a check the student's code skips is missed there; a
 * bare `if (!holds) fail_msg(...)` writes none. */
#define assert_true_why(holds, ...)                                                                                \
    do {                                                                                                           \
        const int holds_ = (holds) != 0;                                                                           \
        answers_record("true %d", holds_);                                                                         \
        if (!holds_)                                                                                               \
            fail_msg(__VA_ARGS__);                                                                                 \
    } while (0)
#define assert_close_why(expected, actual, tolerance, input, hint, suspects, n)                                     \
    check_close_why((double)(expected), (double)(actual), (double)(tolerance), input, hint, suspects, n, __FILE__, \
                    __LINE__)
void check_close_why(double expected, double actual, double tolerance, const char *input, const char *hint,
                     const suspect *suspects, size_t n, const char *file, int line);
#define assert_vec3_why(expected, actual, tolerance, input, hint, suspects, n)                                      \
    check_vec3_why((expected), (actual), (double)(tolerance), input, hint, suspects, n, __FILE__, __LINE__)
void check_vec3_why(vec3 expected, vec3 actual, double tolerance, const char *input, const char *hint,
                    const suspect_vec3 *suspects, size_t n, const char *file, int line);

/* printf into one of eight static buffers in turn: the input of a check,
 * for its message, which may be built from the one before. */
const char *describe(const char *format, ...) __attribute__((format(printf, 1, 2)));

/* A reproducible random sequence: a linear congruential generator whose
 * state the suite seeds (a fixed seed: the same numbers on every run).
 * suite_uniform: a double in [0, 1) from the top 53 bits of the state;
 * suite_random_unit: a unit vector, uniform over directions (rejection from
 * the cube, lengths 0.1 to 1 kept, then normalized). */
double suite_uniform(unsigned long *state);
vec3 suite_random_unit(unsigned long *state);

/* The folder of the Cornell corpus (../shared/cornell/sp17-ray1/data, or
 * $RT_CORNELL), or NULL when it is absent: tests that use it skip then.
 * With RT_REQUIRE_CORNELL set (CI, where the corpus is always beside the
 * clone), an absent corpus fails the test instead. */
const char *cornell_data(void);

#endif
