/* exercise.c - the line an unfinished exercise prints (see exercise.h). */
#include "exercise.h"

#include <stdio.h>
#include <string.h>

void exercise_announce(const char *chapter, const char *file, const char *exercise, const char *function)
{
    /* "01_camera_rays" -> "01": the chapter's number. */
    int number = (int)strcspn(chapter, "_");
    /* One fprintf: stdio locks the stream, so lines from two threads do not interleave. */
    fprintf(stderr,
            "chapter %.*s: %s is still an exercise (TODO %s in chapters/%s/%s); it returns a placeholder, "
            "so the images lack what it computes: the background, black or an unlit surface where it is needed, "
            "as chapters/%s/README.md says under Exercises (make REFERENCE=%.*s links the reference chapter %.*s "
            "instead)\n",
            number, chapter, function, exercise, chapter, file, chapter, number, chapter, number, chapter);
}
