/* interp_stage.h - chapter 10: the stage, as the renderer describes it.
 *
 * Chapter 10's renderer is chapter 05's shading_stage with this chapter's
 * shade function, knobs and features.  The stage is built here, not in
 * render.c, so that chapter 11 renders with exactly this stage and changes
 * one thing, the closest-hit query:
 *
 *     static int grid_faces(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t n)
 *     {
 *         return face_query_build(list, desc, grid_query, q, err, n);
 *     }
 *     ...
 *     shading_stage stage = interp_stage(grid_faces);
 *
 * and so gives byte-identical images, only faster.
 */
#ifndef CH10_INTERP_STAGE_H
#define CH10_INTERP_STAGE_H

#include "05_lambert/shading_stage.h"
#include "10_interpolation/face_query.h"
#include "10_interpolation/shade_interp.h"

/* The knobs' values: the targets of the stage's knobs (the defaults until
 * the command line changes them). */
extern interp_knobs interp_settings;

/* Chapter 04's linear scan with the face table: a build_query_fn. */
int interp_query_linear(const surface_list *list, const scene *desc, hit_query *q, char *err, size_t err_size);

/* Chapter 10's stage over the query `build` makes (a face_query around the
 * real one; NULL: interp_query_linear). */
shading_stage interp_stage(build_query_fn build);

#endif
