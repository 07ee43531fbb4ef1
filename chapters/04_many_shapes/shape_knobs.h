/* shape_knobs.h - chapter 04: the knobs of chapters 02 and 03 on every later renderer.
 *
 * From chapter 04 on every renderer intersects spheres and triangles through
 * the surface list, and takes the same two knobs for them:
 *   --sphere=robust|textbook     chapter 02's formula (robust by default);
 *   --triangle=cramer|watertight chapter 03's test (TRIANGLE_TEST_DEFAULT).
 * A renderer's main owns their values (a shape_knobs) and lists their rows.
 */
#ifndef CH04_SHAPE_KNOBS_H
#define CH04_SHAPE_KNOBS_H

#include "03_triangle/triangle_stage.h"
#include "04_many_shapes/surface.h"
#include "options.h"

typedef struct {
    int sphere, triangle; /* the index of the word chosen; chapter 03's are in triangle_test's order */
} shape_knobs;
#define SHAPE_KNOBS_DEFAULT {.sphere = 0, .triangle = TRIANGLE_TEST_DEFAULT}

/* The rows of --sphere and --triangle, aimed at *k, into rows[0 .. SHAPE_KNOBS - 1];
 * then what they chose, for the surface list. */
enum { SHAPE_KNOBS = 2 };
void shape_knob_rows(shape_knobs *k, knob rows[SHAPE_KNOBS]);
sphere_formula chosen_sphere_formula(const shape_knobs *k);
triangle_test chosen_triangle_test(const shape_knobs *k);

#endif
