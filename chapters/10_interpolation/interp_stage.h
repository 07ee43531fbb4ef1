/* interp_stage.h - chapter 10: the stage, as the renderer describes it.
 *
 * Chapter 10's renderer is chapter 05's shading_stage with this chapter's
 * shade function, knobs and features.  The stage is built here, not in
 * render.c, so that chapter 11 renders with exactly this stage and changes
 * one thing, the closest-hit query, `interp_stage(grid_query)`, and so
 * gives byte-identical images, only faster.
 */
#ifndef CH10_INTERP_STAGE_H
#define CH10_INTERP_STAGE_H

#include "05_lambert/shading_stage.h"
#include "10_interpolation/shade_interp.h"

/* The knobs' values: the targets of the stage's knobs (the defaults until
 * the command line changes them). */
extern interp_knobs interp_settings;

/* Chapter 10's stage over the query `build` makes (NULL: chapter 04's
 * linear scan). */
shading_stage interp_stage(build_query_fn build);

#endif
