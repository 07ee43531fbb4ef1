/* shape_knobs.h - chapter 04: --sphere=robust|textbook (chapter 02) and --triangle=cramer|watertight
 * (chapter 03), the knobs of every later renderer, whose main owns their values. */
#ifndef CH04_RENDERER_SHAPE_KNOBS_H
#define CH04_RENDERER_SHAPE_KNOBS_H

#include "03_triangle/triangle_stage.h"
#include "04_many_shapes/surface.h"
#include "options.h"

typedef struct {
    int sphere, triangle; /* the word chosen: a sphere_formula and a triangle_test, in their enums' order */
} shape_knobs;
#define SHAPE_KNOBS_DEFAULT {.sphere = 0, .triangle = TRIANGLE_TEST_DEFAULT}

/* The rows of --sphere and --triangle, aimed at *k. */
enum { SHAPE_KNOBS = 2 };
void shape_knob_rows(shape_knobs *k, knob rows[SHAPE_KNOBS]);

#endif
