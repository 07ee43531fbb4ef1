/* triangle_explain.h - chapter 03: a triangle test as --explain reports it (in triangle_stage.c). */
#ifndef CH03_TRIANGLE_EXPLAIN_H
#define CH03_TRIANGLE_EXPLAIN_H

#include "03_triangle/triangle.h"

/* Reports the test triangle_intersect just made; for a miss, where the whole
 * line meets the triangle, or that it passes outside it. */
void triangle_explain(const triangle *tri, ray r, real t_min, real t_max, triangle_test test, bool found,
                      const triangle_hit *hit);

#endif
