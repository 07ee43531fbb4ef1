/* shape_knobs.h - chapter 04: the knobs of chapters 02 and 03 on every later renderer.
 *
 * From chapter 04 on every renderer intersects spheres and triangles through
 * the surface list, and takes the same two knobs for them:
 *   --sphere=robust|textbook     chapter 02's formula (robust by default);
 *   --triangle=cramer|watertight chapter 03's test (TRIANGLE_TEST_DEFAULT).
 * A renderer lists shape_knobs among its knobs and, once they are parsed,
 * builds its surface list with the chosen formula and test.
 */
#ifndef CH04_SHAPE_KNOBS_H
#define CH04_SHAPE_KNOBS_H

#include "04_many_shapes/surface.h"
#include "options.h"

enum { SHAPE_KNOBS = 2 };
extern const knob shape_knobs[SHAPE_KNOBS];

/* What --sphere and --triangle chose. */
sphere_formula chosen_sphere_formula(void);
triangle_test chosen_triangle_test(void);

#endif
