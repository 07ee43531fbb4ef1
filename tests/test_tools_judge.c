/* The grader's verdict from two transcripts (tools/judge.c): what passes,
 * what a forged or broken transcript gets, and why. */
#include <stdio.h>
#include <string.h>

#include "../tools/judge.h"
#include "suite.h"

/* The reference's run of a test: three checks and an answer, in double. */
static const char reference[] = "eps 0x1p-52\n"
                                "close 0x1.eb851eb851eb8p-2 0x1.eb851eb851ebap-2 0x1.6p-44\n" /* 0.48 within 8e-14 */
                                "close 0x1p-2 0x1p-2 0x0p+0\n"                                /* L.r against L.g */
                                "int 2 2\n"
                                "true 1\n"
                                "answer 0x1.7p-3 0x1p-40 lambert(...).x\n" /* 0.1796875 */
                                "end 0\n";

static judge_verdict verdict(const char *student, char *note)
{
    return judge(reference, student, note, 200);
}

static void test_the_same_records_pass(void **state)
{
    (void)state;
    char note[200] = "";
    assert_int_equal(JUDGE_PASSED, verdict(reference, note));
}

/* Within the reference's tolerance of the student's own expected value,
 * which is the reference's: 0.48 + 4e-14 passes, 0.48 + 1e-13 does not. */
static void test_a_check_within_its_tolerance(void **state)
{
    (void)state;
    char note[200] = "";
    const char *near = "eps 0x1p-52\nclose 0x1.eb851eb851eb8p-2 0x1.eb851eb852189p-2 0\nclose 0x1p-2 0x1p-2 0\n"
                       "int 2 2\ntrue 1\nanswer 0x1.7p-3 0x1p-40 x\nend 0\n"; /* 0.48 + 4e-14 */
    assert_int_equal(JUDGE_PASSED, verdict(near, note));
    const char *far = "eps 0x1p-52\nclose 0x1.eb851eb851eb8p-2 0x1.eb851eb8525c1p-2 0\nclose 0x1p-2 0x1p-2 0\n"
                      "int 2 2\ntrue 1\nanswer 0x1.7p-3 0x1p-40 x\nend 0\n"; /* 0.48 + 1e-13 */
    assert_int_equal(JUDGE_FAILED, verdict(far, note));
    assert_string_equal("check 1 of the test fails", note);
}

/* An expected value computed from the student's own answer (L.r against
 * L.g) may differ from the reference's by the roundings of another correct
 * formula (4096 REAL_EPSILON of it), never more: a student cannot choose
 * its own expected values. */
static void test_expected_values_anchored_to_the_reference(void **state)
{
    (void)state;
    char note[200] = "";
    const char *rounded = "eps 0x1p-52\nclose 0x1.eb851eb851eb8p-2 0x1.eb851eb851ebap-2 0\n"
                          "close 0x1.0000000000009p-2 0x1.0000000000009p-2 0\nint 2 2\ntrue 1\n"
                          "answer 0x1.7p-3 0x1p-40 x\nend 0\n";
    assert_int_equal(JUDGE_PASSED, verdict(rounded, note)); /* 9 ulps from 0.25 */
    const char *forged = "eps 0x1p-52\nclose 0x0p+0 0x0p+0 0\nclose 0x0p+0 0x0p+0 0\nint 2 2\ntrue 1\n"
                         "answer 0x1.7p-3 0x1p-40 x\nend 0\n"; /* a zero lambert that says 0 was expected */
    assert_int_equal(JUDGE_FAILED, verdict(forged, note));
    assert_string_equal("check 1 of the test fails", note);
}

/* An answer to an input drawn at grading time: within its tolerance of the
 * reference's answer; the note names the input and both values. */
static void test_answers_against_the_reference(void **state)
{
    (void)state;
    char note[200] = "";
    const char *wrong = "eps 0x1p-52\nclose 0x1.eb851eb851eb8p-2 0x1.eb851eb851ebap-2 0\nclose 0x1p-2 0x1p-2 0\n"
                        "int 2 2\ntrue 1\nanswer 0x0p+0 0x1p-40 x\nend 0\n";
    assert_int_equal(JUDGE_FAILED, verdict(wrong, note));
    assert_string_equal("lambert(...).x: yours 0, the reference's 0.1796875 (within 9.09e-13)", note);
    const char *nan = "eps 0x1p-52\nclose 0x1.eb851eb851eb8p-2 0x1.eb851eb851ebap-2 0\nclose 0x1p-2 0x1p-2 0\n"
                      "int 2 2\ntrue 1\nanswer nan 0x1p-40 x\nend 0\n";
    assert_int_equal(JUDGE_FAILED, verdict(nan, note));
    const char *both_nan_ref = "eps 0x1p-52\nanswer nan 0x0p+0 a NaN\nend 0\n";
    const char *both_nan = "eps 0x1p-52\nanswer nan 0x1p-40 x\nend 0\n";
    assert_int_equal(JUDGE_PASSED, judge(both_nan_ref, both_nan, note, sizeof note));
}

/* Integers equal and the reference's; a truth true; the same records in
 * the same order, ended by "end 0". */
static void test_records_and_their_order(void **state)
{
    (void)state;
    char note[200] = "";
    const char *head = "eps 0x1p-52\nclose 0x1.eb851eb851eb8p-2 0x1.eb851eb851ebap-2 0\nclose 0x1p-2 0x1p-2 0\n";
    char text[400];
    const char *const tails[] = {
        "int 3 3\ntrue 1\nanswer 0x1.7p-3 0x1p-40 x\nend 0\n",         /* equal, but not the reference's 2 */
        "int 2 2\ntrue 0\nanswer 0x1.7p-3 0x1p-40 x\nend 0\n",         /* an assertion that failed */
        "int 2 2\ntrue 1\nanswer 0x1.7p-3 0x1p-40 x\n",                /* stopped before the end (an exit) */
        "int 2 2\ntrue 1\nanswer 0x1.7p-3 0x1p-40 x\nend 1\n",         /* the suite itself counted a failure */
        "int 2 2\ntrue 1\nanswer 0x1.7p-3 0x1p-40 x\nend 0\nend 0\n", /* more than the reference */
        "int 2 2\nfail\ntrue 1\nanswer 0x1.7p-3 0x1p-40 x\nend 0\n",   /* a fail_msg */
        "int 2 2\nPASSED\nanswer 0x1.7p-3 0x1p-40 x\nend 0\n",         /* not a record */
    };
    for (size_t k = 0; k < sizeof tails / sizeof tails[0]; k++) {
        snprintf(text, sizeof text, "%s%s", head, tails[k]);
        assert_int_equal(JUDGE_FAILED, verdict(text, note));
    }
    assert_int_equal(JUDGE_FAILED, verdict("", note)); /* nothing at all: a crash before the first check */
    assert_string_equal("the test stopped before its check 1 (a failed check, a crash or an exit)", note);
}

/* The reference's run decides a skip, and a reference that does not pass
 * is the grader's problem, said so. */
static void test_what_the_reference_says(void **state)
{
    (void)state;
    char note[200] = "";
    assert_int_equal(JUDGE_SKIPPED, judge("eps 0x1p-52\nskip\nend 0\n", "", note, sizeof note));
    assert_int_equal(JUDGE_BROKEN, judge("eps 0x1p-52\nclose 1 2 0\nend 1\n", reference, note, sizeof note));
    assert_int_equal(JUDGE_BROKEN, judge("eps 0x1p-52\nclose 1 1 0\n", reference, note, sizeof note));
}

static const graded_test tests[] = {
    GRADED(test_the_same_records_pass, 0),
    GRADED(test_a_check_within_its_tolerance, 0),
    GRADED(test_expected_values_anchored_to_the_reference, 0),
    GRADED(test_answers_against_the_reference, 0),
    GRADED(test_records_and_their_order, 0),
    GRADED(test_what_the_reference_says, 0),
};

SUITE_MAIN("tools_judge", tests)
