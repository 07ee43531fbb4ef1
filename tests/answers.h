/* answers.h - what a suite tells the grader: answers, never verdicts.
 *
 * Graded, a test runs twice (tools/grade): once linked with the reference
 * (trusted: no student code in that process) and once with the student's
 * exercise files, each as `SUITE --only NAME --answers FD --seed SEED`.
 * Every check then writes on FD what it compares, one record a line, before
 * it decides anything:
 *
 *     eps E                  the build's REAL_EPSILON (first)
 *     close E A T            assert_close and friends (a vec3: one a component)
 *     int A B                assert_int_equal
 *     true V                 assert_true, _false, _null, _non_null, strings, memory
 *     fail / skip            fail_msg, fail, skip
 *     answer A T WHAT        an answer to an input drawn from SEED (suite_answer)
 *     end FAILED             after the last test
 *
 * The grader, never the process that ran the student's code, decides: the
 * student's records must be those of the reference's run, each as the check
 * would judge it with the reference's tolerances, and each answer within its
 * tolerance of the reference's answer (tools/grade.c, "The verdict").
 *
 * Inputs drawn at grading time: a suite may add, in tests/seeded/NN_name.c,
 * a check for each graded test that draws inputs from the grader's seed
 * (one the student never sees before grading) and gives the exercise's
 * answers to them with suite_answer; the reference's run computes the
 * expected values then, so no table of the suite's published inputs can
 * pass.  Outside grading (no --answers) they do not run.
 */
#ifndef RT_TESTS_ANSWERS_H
#define RT_TESTS_ANSWERS_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "color.h"
#include "vec3.h"

/* suite_main: start writing records on fd, and end them. */
void answers_open(int fd);
void answers_end(int failed);
/* One record (a line, printf-formatted), when answers are on. */
void answers_record(const char *format, ...) __attribute__((format(printf, 1, 2)));

/* An answer to an input drawn from the seed: `what` says which (the
 * function and its input, shown when it differs from the reference's);
 * tolerance is how far it may be from the reference's answer (the
 * reference's run gives it; a NaN answer matches only a NaN). */
void suite_answer(const char *what, double value, double tolerance);
void suite_answer_vec3(const char *what, vec3 value, double tolerance);
/* A colour's three channels, named .r, .g and .b. */
void suite_answer_rgb(const char *what, color value, double tolerance);

/* A graded test's check of inputs drawn at grading time: draws them from
 * *state (suite_uniform, suite_random_unit) and calls suite_answer. */
typedef void (*seeded_fn)(unsigned long *state);
typedef struct {
    const char *test; /* the graded test it belongs to */
    seeded_fn check;
} seeded_check;
#define SEEDED(test, check) {#test, check}
/* In tests/seeded/NN_name.c: SEEDED_CHECKS(SEEDED(test_a, seeded_a), ...) */
#define SEEDED_CHECKS(...) const seeded_check suite_seeded_checks[] = {__VA_ARGS__, {NULL, NULL}};
/* The seeded check of test `name`, or NULL; all of them (NULL-terminated), or NULL. */
const seeded_check *seeded_for(const char *name);
const seeded_check *seeded_all(void);

/* cmocka's checks, each writing its record first. */
void suite_assert_true(LargestIntegralType holds, const char *expression, const char *file, int line);
void suite_assert_int(LargestIntegralType a, LargestIntegralType b, int equal, const char *file, int line);
void suite_assert_string(const char *a, const char *b, const char *file, int line);
void suite_assert_memory(const void *a, const void *b, size_t size, int equal, const char *file, int line);
void suite_fail(const char *file, int line);
void suite_skip(const char *file, int line);

#undef assert_true
#define assert_true(c) suite_assert_true(cast_to_largest_integral_type(c) != 0, #c, __FILE__, __LINE__)
#undef assert_false
#define assert_false(c) suite_assert_true(cast_to_largest_integral_type(c) == 0, "!(" #c ")", __FILE__, __LINE__)
#undef assert_non_null
#define assert_non_null(c) suite_assert_true((c) != NULL, #c, __FILE__, __LINE__)
#undef assert_null
#define assert_null(c) suite_assert_true((c) == NULL, "!(" #c ")", __FILE__, __LINE__)
#undef assert_int_equal
#define assert_int_equal(a, b)                                                                                     \
    suite_assert_int(cast_to_largest_integral_type(a), cast_to_largest_integral_type(b), 1, __FILE__, __LINE__)
#undef assert_int_not_equal
#define assert_int_not_equal(a, b)                                                                                 \
    suite_assert_int(cast_to_largest_integral_type(a), cast_to_largest_integral_type(b), 0, __FILE__, __LINE__)
#undef assert_string_equal
#define assert_string_equal(a, b) suite_assert_string((const char *)(a), (const char *)(b), __FILE__, __LINE__)
#undef assert_memory_equal
#define assert_memory_equal(a, b, size)                                                                            \
    suite_assert_memory((const void *)(a), (const void *)(b), size, 1, __FILE__, __LINE__)
#undef assert_memory_not_equal
#define assert_memory_not_equal(a, b, size)                                                                        \
    suite_assert_memory((const void *)(a), (const void *)(b), size, 0, __FILE__, __LINE__)
#undef fail
#define fail() suite_fail(__FILE__, __LINE__)
#undef skip
#define skip() suite_skip(__FILE__, __LINE__)

#endif
