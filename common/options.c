#include "options.h"

#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define MAX_KNOBS 24
#define MAX_IMAGE_SIDE 16384

enum { OPT_SEED = 256, OPT_NONFINITE, OPT_EXPLAIN, OPT_EXPLAIN_JSON, OPT_EXPLAIN_PICTURE, OPT_KNOB = 512 };

static const char *const nonfinite_modes[] = {[NONFINITE_DROP] = "drop", [NONFINITE_SHOW] = "show",
                                              [NONFINITE_FAIL] = "fail", NULL};

/* "PROGRAM: problem (see --help)": every option error names the program and the help. */
static void option_error(FILE *err, const char *program, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fprintf(err, "%s: ", program);
    vfprintf(err, format, args);
    fprintf(err, " (see --help)\n");
    va_end(args);
}

static bool parse_long(const char *s, long min, long max, long *out)
{
    char *end;
    errno = 0;
    long value = strtol(s, &end, 10);
    if (errno || end == s || *end != '\0' || value < min || value > max)
        return false;
    *out = value;
    return true;
}

static bool parse_size(const char *s, int *width, int *height)
{
    char *end;
    errno = 0;
    long w = strtol(s, &end, 10);
    if (errno || end == s || (*end != 'x' && *end != 'X'))
        return false;
    long h;
    if (!parse_long(end + 1, 1, MAX_IMAGE_SIDE, &h) || w < 1 || w > MAX_IMAGE_SIDE)
        return false;
    *width = (int)w;
    *height = (int)h;
    return true;
}

/* "X,Y": two non-negative integers below MAX_IMAGE_SIDE. */
static bool parse_pixel(const char *s, int *x, int *y)
{
    char *end;
    errno = 0;
    long a = strtol(s, &end, 10);
    long b;
    if (errno || end == s || *end != ',' || a < 0 || a >= MAX_IMAGE_SIDE ||
        !parse_long(end + 1, 0, MAX_IMAGE_SIDE - 1, &b))
        return false;
    *x = (int)a;
    *y = (int)b;
    return true;
}

static bool is_square(long n)
{
    long root = 1;
    while (root * root < n)
        root++;
    return root * root == n;
}

/* Whether v is inside the range of number knob k (knob.choices); if not, the message names the
 * option, the value and the range. */
static bool in_range(const knob *k, const char *what, double v, const char *value, const char *program, FILE *err)
{
    if (!k->choices)
        return true;
    const char *low = k->choices[0], *high = k->choices[1];
    bool above = low[0] == '>';
    double lowest = strtod(low + above, NULL), highest = high ? strtod(high, NULL) : INFINITY;
    if ((above ? v > lowest : v >= lowest) && v <= highest)
        return true;
    if (above)
        option_error(err, program, "--%s: '%s' is not %s above %s%s%s", k->name, value, what, low + 1,
                     high ? " and at most " : "", high ? high : "");
    else
        option_error(err, program, "--%s: '%s' is not %s from %s%s%s", k->name, value, what, low,
                     high ? " to " : " up", high ? high : "");
    return false;
}

static bool set_knob(const knob *k, const char *value, const char *program, FILE *err)
{
    switch (k->kind) {
    case KNOB_CHOICE:
        for (int c = 0; k->choices[c]; c++) {
            if (strcmp(k->choices[c], value) == 0) {
                *(int *)k->target = c;
                return true;
            }
        }
        char words[256] = "";
        size_t len = 0;
        for (int c = 0; k->choices[c] && len < sizeof words; c++)
            len += (size_t)snprintf(words + len, sizeof words - len, " %s", k->choices[c]);
        option_error(err, program, "--%s: '%s' is not one of:%s", k->name, value, words);
        return false;
    case KNOB_INT: {
        long v;
        if (!parse_long(value, INT_MIN, INT_MAX, &v)) {
            option_error(err, program, "--%s: '%s' is not an integer", k->name, value);
            return false;
        }
        if (!in_range(k, "an integer", (double)v, value, program, err))
            return false;
        *(int *)k->target = (int)v;
        return true;
    }
    case KNOB_REAL: {
        char *end;
        errno = 0;
        double v = strtod(value, &end);
        if (errno || end == value || *end != '\0' || !isfinite(v)) {
            option_error(err, program, "--%s: '%s' is not a finite number", k->name, value);
            return false;
        }
        if (!in_range(k, "a number", (double)(real)v, value, program, err)) /* the value the knob will hold */
            return false;
        *(real *)k->target = (real)v;
        return true;
    }
    }
    return false;
}

static void print_knob_default(const knob *k, FILE *out)
{
    switch (k->kind) {
    case KNOB_CHOICE:
        fprintf(out, " (");
        for (int c = 0; k->choices[c]; c++)
            fprintf(out, "%s%s", c ? "|" : "", k->choices[c]);
        fprintf(out, "; default %s)", k->choices[*(const int *)k->target]);
        break;
    case KNOB_INT:
        fprintf(out, " (default %d)", *(const int *)k->target);
        break;
    case KNOB_REAL:
        fprintf(out, " (default %g)", (double)*(const real *)k->target);
        break;
    }
}

static void print_help(const char *program, const char *summary, const char *default_output, const knob *knobs,
                       int n_knobs, FILE *out)
{
    fprintf(out,
            "%s\n"
            "usage: %s [options] [scene.xml]\n"
            "  scene.xml           a scene file (see docs/scenes.md); without one, the built-in scene\n"
            "  -o, --output FILE   the PNG to write (default: %s in the current folder)\n"
            "  -s, --size WxH      image size in pixels (default: the scene's)\n"
            "  -n, --samples N     samples per pixel, a square number (default: the scene's, else 1)\n"
            "  -j, --threads N     threads to render with (default: all cores)\n"
            "      --seed N        seed for the sub-pixel sample positions (default 0)\n"
            "  -q, --quiet         no progress line and no summary\n"
            "      --nonfinite=M   a sample whose radiance is NaN or infinite is counted and: drop (left out\n"
            "                      of its pixel; the default), show (its pixel painted magenta), or fail\n"
            "                      (no image written, exit status 3)\n"
            "      --explain X,Y   also print the rays behind pixel (X, Y), column and row from the image's\n"
            "                      top-left corner, with every number the lecture's equations took\n"
            "      --explain-json FILE     the same tree as JSON\n"
            "      --explain-picture FILE  a PNG of the image and of the pixel's rays seen from above and\n"
            "                              from the side\n"
            "  -h, --help          this text\n",
            summary, program, default_output);
    if (n_knobs > 0)
        fprintf(out, "knobs (the earlier chapters' first), each with its choices and default:\n");
    int width = 12; /* the helps in one column, two spaces past the longest name (24 at least) */
    for (int k = 0; k < n_knobs; k++)
        width = (int)strlen(knobs[k].name) > width ? (int)strlen(knobs[k].name) : width;
    for (int k = 0; k < n_knobs; k++) {
        fprintf(out, "      --%s=V%*s%s", knobs[k].name, width + 2 - (int)strlen(knobs[k].name), "", knobs[k].help);
        print_knob_default(&knobs[k], out);
        fputc('\n', out);
    }
    fprintf(out, "real is %s in this build.\n", REAL_NAME);
}

options_result options_parse(int argc, char **argv, const char *summary, const char *default_output,
                             const knob *knobs, int n_knobs, render_options *opt, FILE *out, FILE *err)
{
    *opt = (render_options){0};
    if (n_knobs > MAX_KNOBS) {
        fprintf(err, "%s: too many knobs (%d > %d)\n", argv[0], n_knobs, MAX_KNOBS);
        return OPTIONS_ERROR;
    }
    struct option longs[11 + MAX_KNOBS + 1] = {
        {"output", required_argument, NULL, 'o'}, {"size", required_argument, NULL, 's'},
        {"samples", required_argument, NULL, 'n'}, {"threads", required_argument, NULL, 'j'},
        {"seed", required_argument, NULL, OPT_SEED}, {"quiet", no_argument, NULL, 'q'},
        {"help", no_argument, NULL, 'h'}, {"nonfinite", required_argument, NULL, OPT_NONFINITE},
        {"explain", required_argument, NULL, OPT_EXPLAIN}, {"explain-json", required_argument, NULL, OPT_EXPLAIN_JSON},
        {"explain-picture", required_argument, NULL, OPT_EXPLAIN_PICTURE},
    };
    int n_longs = 11;
    for (int k = 0; k < n_knobs; k++)
        longs[n_longs++] = (struct option){knobs[k].name, required_argument, NULL, OPT_KNOB + k};
    longs[n_longs] = (struct option){0};

    /* getopt keeps state between calls (optind, and glibc's position inside a
     * group of short options such as -hq).  optind = 0 resets all of it;
     * optind = 1 would leave the group position behind, and a second parse
     * in one process would misread its arguments. */
    optind = 0;
    opterr = 0;
    int c;
    long value;
    while ((c = getopt_long(argc, argv, ":o:s:n:j:qh", longs, NULL)) != -1) {
        switch (c) {
        case 'o':
            opt->output = optarg;
            break;
        case 's':
            if (!parse_size(optarg, &opt->width, &opt->height)) {
                option_error(err, argv[0], "--size: '%s' is not WxH with sides from 1 to %d", optarg, MAX_IMAGE_SIDE);
                return OPTIONS_ERROR;
            }
            break;
        case 'n':
            if (!parse_long(optarg, 1, 1L << 16, &value) || !is_square(value)) {
                option_error(err, argv[0], "--samples: '%s' is not a square number from 1 to 65536 (1, 4, 9, 16, ...)",
                             optarg);
                return OPTIONS_ERROR;
            }
            opt->samples = (int)value;
            break;
        case 'j':
            if (!parse_long(optarg, 1, 1024, &value)) {
                option_error(err, argv[0], "--threads: '%s' is not a number from 1 to 1024", optarg);
                return OPTIONS_ERROR;
            }
            opt->threads = (int)value;
            break;
        case OPT_SEED: {
            char *end;
            errno = 0;
            unsigned long long seed = strtoull(optarg, &end, 10);
            if (errno || end == optarg || *end || optarg[0] == '-') {
                option_error(err, argv[0], "--seed: '%s' is not a non-negative integer", optarg);
                return OPTIONS_ERROR;
            }
            opt->seed = (unsigned long)seed;
            break;
        }
        case 'q':
            opt->quiet = true;
            break;
        case OPT_NONFINITE: {
            int chosen;
            const knob mode = {"nonfinite", KNOB_CHOICE, &chosen, nonfinite_modes, NULL};
            if (!set_knob(&mode, optarg, argv[0], err))
                return OPTIONS_ERROR;
            opt->nonfinite = (nonfinite_mode)chosen;
            break;
        }
        case OPT_EXPLAIN:
            if (!parse_pixel(optarg, &opt->explain_x, &opt->explain_y)) {
                option_error(err, argv[0], "--explain: '%s' is not X,Y (a pixel's column and row, from 0)", optarg);
                return OPTIONS_ERROR;
            }
            opt->explain = true;
            break;
        case OPT_EXPLAIN_JSON:
            opt->explain_json = optarg;
            break;
        case OPT_EXPLAIN_PICTURE:
            opt->explain_picture = optarg;
            break;
        case 'h':
            print_help(argv[0], summary, default_output, knobs, n_knobs, out);
            return OPTIONS_EXIT;
        case ':':
            option_error(err, argv[0], "%s needs a value", argv[optind - 1]);
            return OPTIONS_ERROR;
        case '?':
            option_error(err, argv[0], "unknown option '%s'", argv[optind - 1]);
            return OPTIONS_ERROR;
        default:
            if (c >= OPT_KNOB && c < OPT_KNOB + n_knobs) {
                if (!set_knob(&knobs[c - OPT_KNOB], optarg, argv[0], err))
                    return OPTIONS_ERROR;
            }
            break;
        }
    }
    if ((opt->explain_json || opt->explain_picture) && !opt->explain) {
        option_error(err, argv[0], "%s needs --explain X,Y (which pixel)",
                     opt->explain_json ? "--explain-json" : "--explain-picture");
        return OPTIONS_ERROR;
    }
    if (optind < argc)
        opt->scene_path = argv[optind++];
    if (optind < argc) {
        option_error(err, argv[0], "one scene file at most, but '%s' follows '%s'", argv[optind], opt->scene_path);
        return OPTIONS_ERROR;
    }
    return OPTIONS_OK;
}

const char *options_output(const render_options *opt, const char *fallback)
{
    return opt->output ? opt->output : fallback;
}
