/* probe_shader.h - a surface that records the rays that reach it (chapters 08 on).
 *
 * The suites of the recursive chapters put a probe in the scene (its shader
 * is probe_shader) and trace with a shade function of their own that asks
 * probe_took() first and shades every other surface with the chapter's
 * shader.  probe holds, in order of arrival, each ray that reached the probe,
 * its depth and the weight of its path (path.h).  probe_trace() empties the
 * record and traces one eye ray.
 *
 * Header only, in static functions and variables: included by one suite.
 */
#ifndef RT_TESTS_PROBE_SHADER_H
#define RT_TESTS_PROBE_SHADER_H

#include <stdbool.h>

#include "08_mirrors/path.h"
#include "shading_suite.h"

#define MAX_PROBES 16
static _Thread_local struct {
    int n; /* every arrival is counted; the first MAX_PROBES are kept */
    ray r[MAX_PROBES];
    int depth[MAX_PROBES];
    color weight[MAX_PROBES];
} probe;
static int probe_shader = -1; /* -1: no probe in the scene */

/* Records the ray of sp when it hit the probe, and says whether it did. */
static inline bool probe_took(const tracer *tr, const shading_point *sp, int depth)
{
    if (probe_shader < 0 || sp->hit.shader != probe_shader)
        return false;
    if (probe.n < MAX_PROBES) {
        probe.r[probe.n] = sp->r;
        probe.depth[probe.n] = depth;
        probe.weight[probe.n] = tr->weight;
    }
    probe.n++;
    return true;
}

/* suite_trace with an empty record. */
static inline color probe_trace(const scene *desc, shade_fn shade, const stage_knobs *knobs, ray r, uint64_t *rays)
{
    probe.n = 0;
    return suite_trace(desc, shade, knobs, r, rays);
}

#endif
