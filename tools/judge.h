/* judge.h - the verdict of a graded test, from two transcripts.
 *
 * A graded test runs twice (tools/grade.c): the reference's suite, which
 * holds no student code, and the student's, each writing the records of
 * tests/answers.h.  judge() decides from the two transcripts alone, so
 * nothing the student's process writes or does says "pass" by itself: it
 * must give the answers the reference's run expects.
 *
 * The rules, record by record (the reference's first):
 *   - the same records in the same order, and both end with "end 0";
 *   - close E A T: the student's A within the reference's T of the
 *     student's E, as the check itself would judge, and that E anchored to
 *     the reference's: equal, or within T + 4096 REAL_EPSILON |E| (an
 *     expected value the test computes from the student's own answers, such
 *     as one channel against another, differs from the reference's by the
 *     roundings of a correct formula written otherwise);
 *   - int A B: A = B and A is the reference's A;
 *   - true V: V is 1;
 *   - answer A T: within T of the reference's answer (NaN only for NaN).
 * A reference that skipped makes the test a skip, one that failed a failure
 * that is the grader's (said so).
 */
#ifndef RT_TOOLS_JUDGE_H
#define RT_TOOLS_JUDGE_H

#include <stddef.h>

typedef enum { JUDGE_PASSED, JUDGE_FAILED, JUDGE_SKIPPED, JUDGE_BROKEN } judge_verdict;

/* The verdict of `student` against `reference` (NUL-terminated texts);
 * why, when not passed, in note (one line, at most note_size bytes). */
judge_verdict judge(const char *reference, const char *student, char *note, size_t note_size);

#endif
