/* exercise.h - an unfinished exercise says so, once, when it is first called.
 *
 * The skeletons in chapters/ are generated from the solutions by
 * tools/skeleton.awk, which starts every stub with
 *
 *     EXERCISE_STUB("01_camera_rays", "camera.c", "perspective");
 *
 * followed by a comment that tells the student to delete the line when done.
 *
 * In a test suite the first call prints one line on stderr, for example
 *
 *     chapter 01: camera_ray is still an exercise (TODO perspective in chapters/01_camera_rays/camera.c);
 *     it returns a placeholder until you write it and delete the EXERCISE_STUB line
 *     (chapters/01_camera_rays/README.md, Exercises)
 *
 * so that a failed test is never a mystery.  A renderer (renderer_main)
 * calls exercise_defer() first: the stubs are then only noted, and
 * exercise_report() prints one line naming all that ran, once the image is
 * done.  Later calls, from any thread, print nothing.  Solutions never call
 * it: a finished exercise is silent once the student has deleted the line,
 * as its comment says.
 */
#ifndef RT_EXERCISE_H
#define RT_EXERCISE_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>

/* Prints the line, or notes the stub after exercise_defer(); called by
 * EXERCISE_STUB at most once per stub. */
void exercise_announce(const char *chapter, const char *file, const char *exercise, const char *function);

/* From now on exercise_announce only notes the stubs, for exercise_report. */
void exercise_defer(void);

/* One line on `out` naming the stubs noted since exercise_defer(), by
 * file:function, for the image `name`; nothing when none ran. */
void exercise_report(FILE *out, const char *name);

/* Set by every call of a stub (read and cleared by the test suites, which
 * then say that a placeholder ran rather than guess at a mistake).  Loaded
 * before it is stored, so that threads calling stubs share its cache line. */
extern atomic_bool exercise_stub_ran;

#define EXERCISE_STUB(chapter, file, exercise)                                                                     \
    do {                                                                                                           \
        if (!atomic_load_explicit(&exercise_stub_ran, memory_order_relaxed))                                       \
            atomic_store_explicit(&exercise_stub_ran, true, memory_order_relaxed);                                 \
        static atomic_flag exercise_told_ = ATOMIC_FLAG_INIT;                                                      \
        if (!atomic_flag_test_and_set(&exercise_told_))                                                            \
            exercise_announce(chapter, file, exercise, __func__);                                                  \
    } while (0)

#endif
