/* exercise.h - an unfinished exercise says so, once, when it is first called.
 *
 * The skeletons in chapters/ are generated from the solutions by
 * tools/skeleton.awk, which starts every stub with
 *
 *     EXERCISE_STUB("01_camera_rays", "camera.c", "perspective");
 *
 * The first call prints one line on stderr, for example
 *
 *     chapter 01: camera_ray is still an exercise (TODO perspective in chapters/01_camera_rays/camera.c);
 *     it returns a placeholder, so the images lack what it computes: the background, black or an unlit surface
 *     where it is needed, as chapters/01_camera_rays/README.md says under Exercises (make REFERENCE=01 links
 *     the reference chapter 01 instead)
 *
 * so that a black image or a failed test is never a mystery.  Later calls,
 * from any thread, print nothing.  Solutions never call it: a finished
 * exercise is silent.
 */
#ifndef RT_EXERCISE_H
#define RT_EXERCISE_H

#include <stdatomic.h>

/* Prints the line; called by EXERCISE_STUB at most once per stub. */
void exercise_announce(const char *chapter, const char *file, const char *exercise, const char *function);

#define EXERCISE_STUB(chapter, file, exercise)                                                                     \
    do {                                                                                                           \
        static atomic_flag exercise_told_ = ATOMIC_FLAG_INIT;                                                      \
        if (!atomic_flag_test_and_set(&exercise_told_))                                                            \
            exercise_announce(chapter, file, exercise, __func__);                                                  \
    } while (0)

#endif
