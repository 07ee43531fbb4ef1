/* shape_knobs.c - chapter 04: the knobs of chapters 02 and 03 on every later renderer. */
#include "04_many_shapes/renderer/shape_knobs.h"

static const char *const sphere_choices[] = {"robust", "textbook", NULL}; /* in sphere_formula's order */

void shape_knob_rows(shape_knobs *k, knob rows[SHAPE_KNOBS])
{
    rows[0] = (knob){"sphere", KNOB_CHOICE, &k->sphere, sphere_choices, "ray-sphere formula (chapter 02)"};
    rows[1] = triangle_knob(&k->triangle);
}
