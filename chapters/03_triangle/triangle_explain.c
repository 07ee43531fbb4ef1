/* triangle_explain.c - chapter 03: a triangle test as --explain reports it. */
#include "03_triangle/triangle_explain.h"

#include "explain.h"

void triangle_explain(const triangle *tri, ray r, real t_min, real t_max, triangle_test test, bool found,
                      const triangle_hit *hit)
{
    if (found) {
        explain_triangle(true, hit->t, hit->beta, hit->gamma, t_min, t_max, true, hit->t);
        return;
    }
    triangle_hit line;
    bool line_hits = triangle_intersect(tri, r, -REAL_INFINITY, REAL_INFINITY, test, &line);
    explain_triangle(false, 0, 0, 0, t_min, t_max, line_hits, line_hits ? line.t : 0);
}
