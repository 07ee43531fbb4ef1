/* shading_suite.h - what the suites of the shading chapters (05 on) share.
 *
 * A scene is traced as the renderer traces it (05_lambert/renderer/shading_stage.h: robust
 * spheres, watertight triangles, the linear scan) with the test's own shade
 * function and knobs.  A scene that cannot be prepared fails the test with
 * the preparation's message.
 *
 * Header only, in static functions: it is included by a chapter's suite,
 * which links the stages of chapter 05 on, and by no other.
 */
#ifndef RT_TESTS_SHADING_SUITE_H
#define RT_TESTS_SHADING_SUITE_H

#include <stdlib.h>

#include "05_lambert/renderer/shading_stage.h"
#include "display.h"
#include "image.h"
#include "render_loop.h"
#include "scene_build.h"
#include "suite.h"

/* desc prepared for tracing with shade and knobs (NULL: none, the defaults) (release it). */
static inline shading_view *suite_view(const scene *desc, shade_fn shade, const stage_knobs *knobs)
{
    char err[256] = "";
    const shading_stage stage = {.name = "test", .shade = shade, .shade_knobs = knobs ? *knobs : (stage_knobs){0}};
    shading_view *view = shading_prepare(&stage, desc, SPHERE_ROBUST, TRIANGLE_WATERTIGHT, err, sizeof err);
    if (!view)
        fail_msg("%s", err);
    return view;
}

/* The radiance of one eye ray r through desc (from t = 0, depth 0); its rays
 * are counted into rays. */
static inline color suite_trace(const scene *desc, shade_fn shade, const stage_knobs *knobs, ray r, uint64_t *rays)
{
    shading_view *view = suite_view(desc, shade, knobs);
    color c = trace(&view->tr, r, 0, REAL_INFINITY, 0, rays);
    shading_release(view);
    return c;
}

/* desc rendered into img (initialized here, w x h, free it) at one sample per
 * pixel on two threads. */
static inline render_stats suite_render(const scene *desc, shade_fn shade, const stage_knobs *knobs, image *img, int w,
                                        int h)
{
    shading_view *view = suite_view(desc, shade, knobs);
    if (image_init(img, w, h) != 0)
        fail_msg("out of memory");
    render_options opt = {.samples = 1, .threads = 2};
    render_stats stats = render_image(img, shading_sample, view, &opt);
    shading_release(view);
    return stats;
}

/* The largest difference, in display bytes of the green channel, between
 * img and a uniform radiance (a furnace's background). */
static inline int suite_worst_byte(const image *img, real uniform)
{
    int back = display_encode(uniform, 1), worst = 0;
    for (long k = 0; k < (long)img->width * img->height; k++) {
        int diff = abs((int)display_encode(img->pixels[k].g, 1) - back);
        worst = diff > worst ? diff : worst;
    }
    return worst;
}

/* A big floor triangle (some 70 across) in the plane y = centre.y around
 * centre, wound so that its normal is +y. */
static inline int suite_add_floor(scene *desc, int shader, vec3 centre)
{
    vec3 c = centre;
    return scene_add_surface(desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = shader,
                                                   .v0 = vec3_add(c, vec3_make(-30, 0, 30)),
                                                   .v1 = vec3_add(c, vec3_make(30, 0, 30)),
                                                   .v2 = vec3_add(c, vec3_make(0, 0, -40))});
}

/* ---- the shading point an eye ray meets ------------------------------------------------------- */

static _Thread_local shading_point suite_recorded;
static _Thread_local bool suite_has_recorded;
static inline color suite_record(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    (void)tr;
    (void)depth;
    (void)rays;
    suite_recorded = *sp;
    suite_has_recorded = true;
    return color_make(0, 0, 0);
}

/* The shading point *sp the eye ray r meets in desc, as the shade function
 * is given it; the view (its tracer carries knobs) stays alive for the test
 * to shade or cast from that point: release it. */
static inline shading_view *suite_shading_point(const scene *desc, const stage_knobs *knobs, ray r,
                                                shading_point *sp)
{
    shading_view *view = suite_view(desc, suite_record, knobs);
    uint64_t rays[RAY_KINDS] = {0};
    suite_has_recorded = false;
    trace(&view->tr, r, 0, REAL_INFINITY, 0, rays);
    if (!suite_has_recorded) /* else *sp would be the point of an earlier call */
        fail_msg("the eye ray p = (%g, %g, %g), d = (%g, %g, %g) met nothing in the test's scene", (double)r.p.x,
                 (double)r.p.y, (double)r.p.z, (double)r.d.x, (double)r.d.y, (double)r.d.z);
    *sp = suite_recorded;
    return view;
}

#endif
