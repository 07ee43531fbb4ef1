/* path.c - chapter 08: how deep the recursion goes, and how little it may carry. */
#include "08_mirrors/path.h"

#include "explain.h"

const path_knobs *tracer_path_knobs(const tracer *tr)
{
    static const path_knobs defaults = PATH_KNOBS_DEFAULT;
    return tr->knobs.path ? tr->knobs.path : &defaults;
}

bool path_next(const tracer *tr, int depth, color k, tracer *next)
{
    const path_knobs *knobs = tracer_path_knobs(tr);
    if (depth >= knobs->depth || depth >= PATH_MAX_DEPTH) { /* the depth is exhausted: the ray brings black */
        EXPLAIN(explain_path_stop(true, depth, 0, 0));
        return false;
    }
    color w = color_mul(tr->weight, k); /* the weight of the new ray's path */
    real largest = real_fmax(w.r, real_fmax(w.g, w.b));
    if (!(largest > 0) || largest < knobs->min_weight) { /* nothing, or too little, to carry */
        EXPLAIN(explain_path_stop(false, depth, largest, knobs->min_weight));
        return false;
    }
    *next = *tr;
    next->weight = w;
    return true;
}
