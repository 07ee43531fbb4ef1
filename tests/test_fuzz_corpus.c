/* The fuzz corpus, replayed: every input in fuzz/corpus/TARGET/ (the seeds
 * and every input that ever broke something) goes through its fuzz target
 * once, with the target's contract checks, and the scene target also reads
 * the chapters' own scenes.  No fuzzing here: `make fuzz` does that.  In the
 * sanitizer build this is the corpus replay of `make test`; a broken
 * contract or a sanitizer report aborts the suite, naming the input. */
#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../fuzz/fuzz.h"
#include "suite.h"

typedef int (*target_fn)(const uint8_t *data, size_t size);

static int replay_file(target_fn target, const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        fail_msg("%s: cannot read", path);
    uint8_t *data = malloc(1 << 20);
    assert_non_null(data);
    size_t size = fread(data, 1, 1 << 20, f);
    fclose(f);
    fuzz_input_name = path;
    target(data, size);
    free(data);
    return 1;
}

static int compare(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* Replays every file matching `pattern`; returns how many. */
static int replay_glob(target_fn target, const char *pattern)
{
    glob_t g;
    int n = 0;
    if (glob(pattern, 0, NULL, &g) == 0) {
        qsort(g.gl_pathv, g.gl_pathc, sizeof *g.gl_pathv, compare);
        for (size_t k = 0; k < g.gl_pathc; k++)
            n += replay_file(target, g.gl_pathv[k]);
        globfree(&g);
    }
    return n;
}

static void replay(target_fn target, const char *name, int at_least)
{
    char pattern[128];
    snprintf(pattern, sizeof pattern, "fuzz/corpus/%s/*", name);
    int n = replay_glob(target, pattern);
    if (n < at_least) /* the corpus is kept in the repository: run from its top */
        fail_msg("fuzz/corpus/%s/ holds %d inputs, fewer than the %d committed", name, n, at_least);
    print_message("%s: %d inputs replayed\n", name, n);
}

static void test_scene_corpus(void **state)
{
    (void)state;
    replay(fuzz_scene, "scene", 10);
    assert_true(replay_glob(fuzz_scene, "chapters/*/scenes/*.xml") > 0);
}

static void test_obj_corpus(void **state)
{
    (void)state;
    replay(fuzz_obj, "obj", 5);
}

static void test_options_corpus(void **state)
{
    (void)state;
    replay(fuzz_options, "options", 5);
}

static void test_texture_corpus(void **state)
{
    (void)state;
    replay(fuzz_texture, "texture", 4);
}

static const graded_test tests[] = {
    GRADED(test_scene_corpus, 0),
    GRADED(test_obj_corpus, 0),
    GRADED(test_options_corpus, 0),
    GRADED(test_texture_corpus, 0),
};
SUITE_MAIN("fuzz_corpus", tests)
