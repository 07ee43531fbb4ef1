/* shape_knobs.c - chapter 04: the knobs of chapters 02 and 03 on every later renderer. */
#include "04_many_shapes/shape_knobs.h"

static const char *const sphere_choices[] = {"robust", "textbook", NULL};
static const sphere_formula sphere_formulas[] = {SPHERE_ROBUST, SPHERE_TEXTBOOK};
static int sphere_choice = 0;
static const triangle_test triangle_tests[] = {TRIANGLE_CRAMER, TRIANGLE_WATERTIGHT};
static int triangle_choice = TRIANGLE_TEST_DEFAULT; /* chapter 03's choices are in the order of the enum */

void shape_knob_rows(knob rows[SHAPE_KNOBS])
{
    rows[0] = (knob){"sphere", KNOB_CHOICE, &sphere_choice, sphere_choices, "ray-sphere formula (chapter 02)"};
    rows[1] = triangle_knob(&triangle_choice);
}

sphere_formula chosen_sphere_formula(void) { return sphere_formulas[sphere_choice]; }

triangle_test chosen_triangle_test(void) { return triangle_tests[triangle_choice]; }
