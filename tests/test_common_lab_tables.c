/* The main() of a lab that prints measurement tables (common/lab_tables.h). */
#include <stdio.h>
#include <string.h>

#include "lab_tables.h"
#include "suite.h"

static int printed[2];
static int print_first(void) { return printed[0]++, 0; }
static int print_second(void) { return printed[1]++, 1; } /* a table that fails: its status goes out */

static const lab_table tables[] = {
    {"--first-table", "the first table", print_first},
    {"--second-table", "the second table", print_second},
};

typedef struct {
    int status;
    char out[1024], err[1024];
} run;

/* Runs lab_tables_main on argv[0] "lab" and up to two arguments (NULL: none), capturing what it prints. */
static run lab(const char *a, const char *b)
{
    static run r;
    char *argv[] = {"lab", (char *)a, (char *)b, NULL};
    int argc = 1 + (a != NULL) + (a != NULL && b != NULL);
    memset(&r, 0, sizeof r);
    memset(printed, 0, sizeof printed);
    FILE *out = fmemopen(r.out, sizeof r.out - 1, "w");
    FILE *err = fmemopen(r.err, sizeof r.err - 1, "w");
    r.status = lab_tables_main("lab: two tables", tables, 2, argc, argv, out, err);
    fclose(out);
    fclose(err);
    return r;
}

/* The flag runs its table, and only that one, and its status is the exit status. */
static void test_runs_the_named_table(void **state)
{
    (void)state;
    run r = lab("--first-table", NULL);
    assert_int_equal(0, r.status);
    assert_int_equal(1, printed[0]);
    assert_int_equal(0, printed[1]);
    assert_string_equal("", r.err);
    r = lab("--second-table", NULL);
    assert_int_equal(1, r.status);
    assert_int_equal(0, printed[0]);
    assert_int_equal(1, printed[1]);
}

/* --help lists every table on standard output. */
static void test_help(void **state)
{
    (void)state;
    run r = lab("--help", NULL);
    assert_int_equal(0, r.status);
    assert_non_null(strstr(r.out, "lab: two tables\nusage: lab --TABLE\n"));
    assert_non_null(strstr(r.out, "--first-table"));
    assert_non_null(strstr(r.out, "the second table"));
    assert_string_equal("", r.err);
}

/* No table, an unknown one, or two: status 2, a line naming the problem, the usage, no table run. */
static void test_bad_arguments(void **state)
{
    (void)state;
    const char *args[][2] = {{NULL, NULL}, {"--third-table", NULL}, {"--first-table", "--second-table"}};
    const char *problems[] = {"lab: name one table\n", "lab: unknown table '--third-table'\n", "lab: name one table\n"};
    for (int k = 0; k < 3; k++) {
        run r = lab(args[k][0], args[k][1]);
        assert_int_equal(2, r.status);
        assert_int_equal(0, printed[0] + printed[1]);
        assert_true(strncmp(r.err, problems[k], strlen(problems[k])) == 0);
        assert_non_null(strstr(r.err, "usage: lab --TABLE"));
        assert_string_equal("", r.out);
    }
}

static const graded_test tests[] = {
    GRADED(test_runs_the_named_table, 0),
    GRADED(test_help, 0),
    GRADED(test_bad_arguments, 0),
};

SUITE_MAIN("common_lab_tables", tests)
