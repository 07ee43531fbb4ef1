/* exercise.c - the line an unfinished exercise prints (see exercise.h). */
#include "exercise.h"

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* The stubs noted after exercise_defer(): each stub announces itself at most
 * once, so there are at most as many as the skeletons have (36); a slot is
 * taken with one atomic increment, so threads never share one. */
enum { MAX_NOTED = 128 };
typedef struct {
    const char *chapter, *file, *exercise, *function;
} noted_stub;
static noted_stub noted[MAX_NOTED];
static atomic_int n_noted;
static atomic_bool deferred;
atomic_bool exercise_stub_ran;

void exercise_defer(void) { atomic_store(&deferred, true); }

void exercise_announce(const char *chapter, const char *file, const char *exercise, const char *function)
{
    if (atomic_load(&deferred)) {
        int k = atomic_fetch_add(&n_noted, 1);
        if (k < MAX_NOTED)
            noted[k] = (noted_stub){chapter, file, exercise, function};
        return;
    }
    /* "01_camera_rays" -> "01": the chapter's number. */
    int number = (int)strcspn(chapter, "_");
    /* One fprintf: stdio locks the stream, so lines from two threads do not interleave.
     * tools/grade.c shows the line up to "); it returns". */
    fprintf(stderr,
            "chapter %.*s: %s is still an exercise (TODO %s in chapters/%s/%s); it returns a placeholder "
            "until you write it and delete the EXERCISE_STUB line (chapters/%s/README.md, Exercises)\n",
            number, chapter, function, exercise, chapter, file, chapter);
}

static int by_place(const void *a, const void *b)
{
    const noted_stub *x = a, *y = b;
    int c = strcmp(x->chapter, y->chapter);
    if (!c)
        c = strcmp(x->file, y->file);
    return c ? c : strcmp(x->function, y->function);
}

void exercise_report(FILE *out, const char *name)
{
    int n = atomic_load(&n_noted);
    if (n > MAX_NOTED)
        n = MAX_NOTED;
    if (n == 0)
        return;
    /* Sorted, so the line does not depend on which thread ran a stub first. */
    qsort(noted, (size_t)n, sizeof noted[0], by_place);
    fprintf(out, "%s: placeholders of unfinished exercises (each says so until its EXERCISE_STUB line is deleted; "
                 "see chapters/NN_name/README.md, Exercises):", name);
    for (int k = 0; k < n; k++)
        fprintf(out, "%s %s/%s: TODO %s (%s)", k ? ";" : "", noted[k].chapter, noted[k].file, noted[k].exercise,
                noted[k].function);
    fprintf(out, "\n");
}
