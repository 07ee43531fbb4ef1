/* shape_knobs.c - chapter 04: the knobs of chapters 02 and 03 on every later renderer. */
#include "04_many_shapes/shape_knobs.h"

static const char *const sphere_choices[] = {"robust", "textbook", NULL};
static const sphere_formula sphere_formulas[] = {SPHERE_ROBUST, SPHERE_TEXTBOOK};
static const triangle_test triangle_tests[] = {TRIANGLE_CRAMER, TRIANGLE_WATERTIGHT};

void shape_knob_rows(shape_knobs *k, knob rows[SHAPE_KNOBS])
{
    rows[0] = (knob){"sphere", KNOB_CHOICE, &k->sphere, sphere_choices, "ray-sphere formula (chapter 02)"};
    rows[1] = triangle_knob(&k->triangle);
}

sphere_formula chosen_sphere_formula(const shape_knobs *k) { return sphere_formulas[k->sphere]; }
triangle_test chosen_triangle_test(const shape_knobs *k) { return triangle_tests[k->triangle]; }
