/* options.c - chapter 08's renderer: the option rows of chapters 06-08's knobs. */
#include "08_mirrors/renderer/options.h"

#define STRING(x) #x
#define DIGITS(x) STRING(x)
static const char *const depth_range[] = {"0", DIGITS(PATH_MAX_DEPTH), NULL}, *const weight_range[] = {"0", NULL};

int path_knob_rows(path_knobs *k, knob *rows, stage_knobs *aimed)
{
    int n = phong_knob_rows(&k->phong, rows, aimed); /* chapters 06-07's first */
    aimed->path = k;
    rows[n++] = (knob){"depth", KNOB_INT, &k->depth, depth_range,
                       "deepest bounce traced (0: eye rays only; at most 256)"};
    rows[n++] = (knob){"min-weight", KNOB_REAL, &k->min_weight, weight_range,
                       "no ray whose path weight (product of k_m, R, 1 - R along it) is below this (0: off)"};
    return n;
}
