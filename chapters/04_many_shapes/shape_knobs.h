/* shape_knobs.h - chapter 04: the knobs of chapters 02 and 03 on every later renderer.
 *
 * From chapter 04 on every renderer intersects spheres and triangles through
 * the surface list, and takes the same two knobs for them:
 *   --sphere=robust|textbook     chapter 02's formula (robust by default);
 *   --triangle=cramer|watertight chapter 03's test (TRIANGLE_TEST_DEFAULT).
 * A renderer lists shape_knob_rows among its knobs and, once they are parsed,
 * builds its surface list with the chosen formula and test.
 */
#ifndef CH04_SHAPE_KNOBS_H
#define CH04_SHAPE_KNOBS_H

#include "03_triangle/triangle_stage.h"
#include "04_many_shapes/surface.h"
#include "options.h"

/* The rows of --sphere and --triangle into rows[0 .. SHAPE_KNOBS - 1]. */
enum { SHAPE_KNOBS = 2 };
void shape_knob_rows(knob rows[SHAPE_KNOBS]);

/* What --sphere and --triangle chose. */
sphere_formula chosen_sphere_formula(void);
triangle_test chosen_triangle_test(void);

#endif
