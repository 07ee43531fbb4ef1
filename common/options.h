/* options.h - the command line shared by every renderer.
 *
 *     render [options] [scene.xml]
 *
 * Every chapter's renderer takes the same options (output, size, samples per
 * pixel, threads, seed, quiet, help) and adds its own accuracy knobs through
 * a table of `knob`s, each a long option such as --sphere=robust.
 */
#ifndef RT_OPTIONS_H
#define RT_OPTIONS_H

#include <stdbool.h>
#include <stdio.h>

#include "real.h"

/* What the render loop does with a sample whose radiance is NaN or infinite
 * (--nonfinite).  Every mode counts them; the summary line gives the count. */
typedef enum {
    NONFINITE_DROP, /* default: leave it out of its pixel's mean (a pixel with no finite sample is black) */
    NONFINITE_SHOW, /* paint its pixel magenta, to find it in the image */
    NONFINITE_FAIL, /* drop it, and fail: no image is written, exit status 3 (make figures) */
} nonfinite_mode;

typedef struct {
    const char *scene_path;  /* the positional argument; NULL: built-in scene */
    const char *output;      /* -o; NULL: the renderer's default */
    int width, height;       /* -s WxH; 0: from the scene, else the default */
    int samples;             /* -n; samples per pixel, a square; 0: from the scene, else 1 */
    int threads;             /* -j; 0: OpenMP's default (all cores) */
    unsigned long seed;      /* --seed; jitters the sub-pixel samples */
    bool quiet;              /* -q; no progress line, no summary */
    nonfinite_mode nonfinite; /* --nonfinite=drop|show|fail */
    bool explain;            /* --explain X,Y: print the rays behind pixel (X, Y) (explain.h) */
    int explain_x, explain_y; /* column from the left, row from the top, as in the PNG */
    const char *explain_json;    /* --explain-json FILE: the same tree as JSON */
    const char *explain_picture; /* --explain-picture FILE: the rays drawn over the scene */
} render_options;

typedef enum {
    KNOB_CHOICE, /* target is an int: the index of the chosen word in choices */
    KNOB_INT,    /* target is an int */
    KNOB_REAL,   /* target is a real */
} knob_kind;

typedef struct {
    const char *name;            /* the long option, without the dashes */
    knob_kind kind;
    void *target;                /* holds the default on entry */
    const char *const *choices;  /* KNOB_CHOICE: the words, NULL-terminated; KNOB_INT, KNOB_REAL: NULL (any
                                  * value) or the range, {lowest, highest} or {lowest, NULL}, numbers in words,
                                  * inclusive but for a lowest written ">x" (above x) */
    const char *help;
} knob;

typedef enum {
    OPTIONS_OK,    /* go on and render */
    OPTIONS_EXIT,  /* --help was printed: exit 0 */
    OPTIONS_ERROR, /* a message was printed: exit 2 */
} options_result;

/* Parses argv.  `summary` is the first line of --help, which says that the
 * image goes to `default_output` without -o.  Messages go to `out` (help)
 * and `err` (errors); an error names the program, the option and the
 * problem, and points to --help. */
options_result options_parse(int argc, char **argv, const char *summary, const char *default_output,
                             const knob *knobs, int n_knobs, render_options *opt, FILE *out, FILE *err);

/* The output path: -o when given, otherwise `fallback`. */
const char *options_output(const render_options *opt, const char *fallback);

#endif
