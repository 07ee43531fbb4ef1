/* The command line shared by every renderer (common/options.h). */
#include <stdio.h>
#include <string.h>

#include "options.h"
#include "suite.h"

typedef struct {
    options_result result;
    render_options opt;
    char out[2048], err[1024];
} parsed;

static int quality = 0;
static int depth = 5;
static real epsilon = (real)1e-3;
static int cells = 8;
static real density = 2;
static const char *const quality_choices[] = {"robust", "textbook", NULL};
static const char *const cells_range[] = {"1", "64", NULL}, *const density_range[] = {">0", NULL};
static const knob knobs[] = {
    {"sphere", KNOB_CHOICE, &quality, quality_choices, "sphere formula"},
    {"depth", KNOB_INT, &depth, NULL, "recursion depth"},
    {"epsilon", KNOB_REAL, &epsilon, NULL, "shadow ray offset"},
    {"cells", KNOB_INT, &cells, cells_range, "an integer with a range"},
    {"density", KNOB_REAL, &density, density_range, "a number above 0"},
};

/* Parses a NULL-terminated argument list, capturing what is printed. */
static parsed parse(const char *first, ...)
{
    static parsed p;
    char *argv[16];
    int argc = 0;
    va_list args;
    va_start(args, first);
    for (const char *a = first; a; a = va_arg(args, const char *))
        argv[argc++] = (char *)a;
    va_end(args);
    argv[argc] = NULL;
    memset(&p, 0, sizeof p);
    FILE *out = fmemopen(p.out, sizeof p.out - 1, "w");
    FILE *err = fmemopen(p.err, sizeof p.err - 1, "w");
    p.result = options_parse(argc, argv, "test renderer", "test.png", knobs, (int)(sizeof knobs / sizeof knobs[0]), &p.opt, out, err);
    fclose(out);
    fclose(err);
    return p;
}

static void test_defaults(void **state)
{
    (void)state;
    parsed p = parse("render", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_null(p.opt.scene_path);
    assert_null(p.opt.output);
    assert_int_equal(0, p.opt.width);
    assert_int_equal(0, p.opt.samples);
    assert_int_equal(0, p.opt.threads);
    assert_false(p.opt.quiet);
    assert_string_equal("fallback.png", options_output(&p.opt, "fallback.png"));
}

static void test_all_shared_options(void **state)
{
    (void)state;
    parsed p = parse("render", "-o", "x.png", "-s", "640x480", "-n", "16", "-j", "2", "--seed", "42", "-q",
                     "scene.xml", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_string_equal("scene.xml", p.opt.scene_path);
    assert_string_equal("x.png", options_output(&p.opt, "fallback.png"));
    assert_int_equal(640, p.opt.width);
    assert_int_equal(480, p.opt.height);
    assert_int_equal(16, p.opt.samples);
    assert_int_equal(2, p.opt.threads);
    assert_int_equal(42, p.opt.seed);
    assert_true(p.opt.quiet);
    assert_int_equal(NONFINITE_DROP, p.opt.nonfinite); /* the default */
    p = parse("render", "--nonfinite=show", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_int_equal(NONFINITE_SHOW, p.opt.nonfinite);
    p = parse("render", "--nonfinite", "fail", NULL);
    assert_int_equal(NONFINITE_FAIL, p.opt.nonfinite);
    p = parse("render", "--output=y.png", "--size=3x5", "--samples=1", "--threads=1", "--quiet", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_string_equal("y.png", p.opt.output);
    assert_int_equal(3, p.opt.width);
    assert_int_equal(5, p.opt.height);
}

/* An option's error is one line: the program, the problem, and where to look. */
static void assert_one_line_naming_program_and_help(const char *option, const char *err)
{
    const char *program = "build/07_blinn_phong/render: ";
    const char *help = " (see --help)\n";
    size_t n = strlen(err);
    if (strncmp(err, program, strlen(program)) != 0 || n < strlen(help) ||
        strcmp(err + n - strlen(help), help) != 0 || strchr(err, '\n') != err + n - 1)
        fail_msg("%s: the message is not one line '%s...%s': '%s'", option, program, help, err);
}

static void test_bad_values_name_the_option(void **state)
{
    (void)state;
    static const char *const bad[][3] = {
        {"-s", "0x10", "--size"},    {"-s", "640", "--size"},     {"-s", "99999x1", "--size"},
        {"-s", "axb", "--size"},     {"-n", "3", "--samples"},    {"-n", "0", "--samples"},
        {"-n", "-4", "--samples"},   {"-j", "0", "--threads"},    {"-j", "two", "--threads"},
        {"--seed", "-1", "--seed"},  {"--sphere", "exact", "--sphere"}, {"--depth", "1.5", "--depth"},
        {"--epsilon", "nan", "--epsilon"}, {"--nonfinite", "zero", "--nonfinite"},
        {"--cells", "0", "--cells"},       {"--cells", "65", "--cells"},     {"--density", "0", "--density"},
        {"--density", "-2", "--density"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        parsed p = parse("build/07_blinn_phong/render", bad[k][0], bad[k][1], NULL);
        if (p.result != OPTIONS_ERROR || !strstr(p.err, bad[k][2]) || !strstr(p.err, bad[k][1]))
            fail_msg("%s %s: result %d, message '%s'", bad[k][0], bad[k][1], p.result, p.err);
        assert_one_line_naming_program_and_help(bad[k][0], p.err);
    }
}

static void test_unknown_option_missing_value_and_extra_scene(void **state)
{
    (void)state;
    parsed p = parse("build/07_blinn_phong/render", "--frobnicate", NULL);
    assert_int_equal(OPTIONS_ERROR, p.result);
    assert_non_null(strstr(p.err, "--frobnicate"));
    assert_one_line_naming_program_and_help("--frobnicate", p.err);
    p = parse("build/07_blinn_phong/render", "-o", NULL);
    assert_int_equal(OPTIONS_ERROR, p.result);
    assert_non_null(strstr(p.err, "-o"));
    assert_one_line_naming_program_and_help("-o", p.err);
    p = parse("build/07_blinn_phong/render", "a.xml", "b.xml", NULL);
    assert_int_equal(OPTIONS_ERROR, p.result);
    assert_non_null(strstr(p.err, "b.xml"));
    assert_one_line_naming_program_and_help("a.xml b.xml", p.err);
}

static void test_knobs_set_their_targets(void **state)
{
    (void)state;
    parsed p = parse("render", "--sphere=textbook", "--depth", "9", "--epsilon=1e-6", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_int_equal(1, quality);
    assert_int_equal(9, depth);
    assert_close(1e-6, epsilon, 1e-6 * REAL_EPSILON);
    quality = 0;
    depth = 5;
    epsilon = (real)1e-3;
}

/* A number knob with a range (knob.choices): its ends are inside it (an exclusive end is not), a
 * value outside it is an option error that names the option, the value and the range. */
static void test_knob_ranges(void **state)
{
    (void)state;
    parsed p = parse("render", "--cells=1", "--density=1e-30", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_int_equal(1, cells);
    assert_close(1e-30, density, 1e-30 * REAL_EPSILON);
    p = parse("render", "--cells=64", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_int_equal(64, cells);
    p = parse("render", "--cells=65", NULL);
    assert_int_equal(OPTIONS_ERROR, p.result);
    assert_string_equal("render: --cells: '65' is not an integer from 1 to 64 (see --help)\n", p.err);
    p = parse("render", "--density=0", NULL);
    assert_int_equal(OPTIONS_ERROR, p.result);
    assert_string_equal("render: --density: '0' is not a number above 0 (see --help)\n", p.err);
    p = parse("render", "--density=1e-60", NULL); /* 0 in the float build: the value the knob would hold */
    assert_int_equal(REAL_MIN > 1e-60 ? OPTIONS_ERROR : OPTIONS_OK, p.result);
    cells = 8;
    density = 2;
}

static void test_help_lists_options_knobs_and_defaults(void **state)
{
    (void)state;
    parsed p = parse("render", "--help", NULL);
    assert_int_equal(OPTIONS_EXIT, p.result);
    const char *expected[] = {"test renderer", "--output", "--size", "--samples", "--threads", "--seed",
                              "--quiet",       "--nonfinite=M", "drop", "show", "fail", "--sphere", "robust|textbook", "default robust", "--depth",
                              "default 5",     "--epsilon", "default 0.001", REAL_NAME,
                              "(default: test.png in the current folder)"};
    for (size_t k = 0; k < sizeof expected / sizeof expected[0]; k++)
        if (!strstr(p.out, expected[k]))
            fail_msg("--help does not mention '%s':\n%s", expected[k], p.out);
}

/* Two parses in one process: the second must not inherit getopt's state
 * (glibc remembers where it was inside "-hq" unless optind is set to 0). */
static void test_two_parses_in_a_row(void **state)
{
    (void)state;
    parsed p = parse("render", "-hq", "first.xml", NULL);
    assert_int_equal(OPTIONS_EXIT, p.result); /* -h stops at once, inside the group */
    p = parse("render", "-qj", "2", "second.xml", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_true(p.opt.quiet);
    assert_int_equal(2, p.opt.threads);
    assert_non_null(p.opt.scene_path);
    assert_string_equal("second.xml", p.opt.scene_path);
    p = parse("render", "-n", "4", "third.xml", NULL);
    assert_int_equal(OPTIONS_OK, p.result);
    assert_int_equal(4, p.opt.samples);
    assert_false(p.opt.quiet);
    assert_string_equal("third.xml", p.opt.scene_path);
}

static const graded_test tests[] = {
    GRADED(test_defaults, 0),
    GRADED(test_all_shared_options, 0),
    GRADED(test_bad_values_name_the_option, 0),
    GRADED(test_unknown_option_missing_value_and_extra_scene, 0),
    GRADED(test_knobs_set_their_targets, 0),
    GRADED(test_knob_ranges, 0),
    GRADED(test_help_lists_options_knobs_and_defaults, 0),
    GRADED(test_two_parses_in_a_row, 0),
};
SUITE_MAIN("common_options", tests)
