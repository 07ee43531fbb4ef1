/* The knob rows of a renderer joined from a family's shared rows and the stage's own (common/joined_knobs.h). */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "joined_knobs.h"
#include "suite.h"

static int shared_value = 1, own_value = 1;
static const knob shared_row = {"shared", KNOB_INT, &shared_value, NULL, "a row every stage of the family has"};
static const knob own_row = {"own", KNOB_INT, &own_value, NULL, "the stage's own row"};

static const renderer stage = {.name = "joined", .summary = "joined: a test renderer", .knobs = &own_row, .n_knobs = 1};

/* renderer_main_joined with the rows of stage after n_first shared rows; what it printed on stdout in out. */
static int run(int n_first, char *out, size_t size, const char *arg1, const char *arg2)
{
    char *argv[] = {"joined", (char *)arg1, (char *)arg2, "--help", NULL};
    fflush(stdout);
    FILE *capture = tmpfile();
    assert_non_null(capture);
    int saved = dup(STDOUT_FILENO);
    dup2(fileno(capture), STDOUT_FILENO);
    int status = renderer_main_joined(&stage, &shared_row, n_first, 4, argv);
    fflush(stdout);
    dup2(saved, STDOUT_FILENO);
    close(saved);
    rewind(capture);
    size_t n = fread(out, 1, size - 1, capture);
    out[n] = '\0';
    fclose(capture);
    return status;
}

/* Both rows parse and reach their targets, the shared row listed first in --help. */
static void test_shared_rows_come_first(void **state)
{
    (void)state;
    char out[4096];
    shared_value = own_value = 1;
    assert_int_equal(0, run(1, out, sizeof out, "--shared=2", "--own=3")); /* --help: exit 0 */
    assert_int_equal(2, shared_value);
    assert_int_equal(3, own_value);
    const char *shared = strstr(out, "--shared=V"), *own = strstr(out, "--own=V");
    assert_non_null(shared);
    assert_non_null(own);
    assert_true(shared < own);
}

/* Without the shared rows, --shared is an unknown option: the join is what makes it one. */
static void test_without_shared_rows_the_option_is_unknown(void **state)
{
    (void)state;
    char out[4096];
    shared_value = own_value = 1;
    assert_int_equal(2, run(0, out, sizeof out, "--shared=2", "--own=3"));
    assert_int_equal(1, shared_value);
}

static const graded_test tests[] = {
    GRADED(test_shared_rows_come_first, 0),
    GRADED(test_without_shared_rows_the_option_is_unknown, 0),
};
SUITE_MAIN("common_joined_knobs", tests)
