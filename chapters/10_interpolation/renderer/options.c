/* options.c - chapter 10's renderer: the option rows of chapters 06-10's knobs. */
#include "10_interpolation/renderer/options.h"

static const char *const normal_source_names[] = {"interpolated", "geometric", NULL};
static const char *const below_policy_names[] = {"flip", "keep", NULL};

int interp_knob_rows(interp_knobs *k, knob *rows, stage_knobs *aimed)
{
    int n = glass_knob_rows(&k->earlier, rows, aimed); /* chapters 06-09's first */
    aimed->interp = k;
    rows[n++] = (knob){"normals", KNOB_CHOICE, &k->normals, normal_source_names,
                       "shading normal of a mesh with vn: interpolated, or geometric (the flat faces)"};
    rows[n++] = (knob){"texture-filter", KNOB_CHOICE, &k->filter, texture_filter_names,
                       "texture lookup: nearest texel (the course's images) or bilinear blend of four"};
    rows[n++] = (knob){"below-surface", KNOB_CHOICE, &k->below, below_policy_names,
                       "a mirror direction below the geometric surface: flip it above, or keep it (speckles)"};
    return n;
}
