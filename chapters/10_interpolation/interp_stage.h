/* interp_stage.h - chapter 10: the stage, as the renderer describes it: chapter 05's shading_stage with
 * this chapter's shade function, knobs and features, which chapter 11 reuses over its grid. */
#ifndef CH10_INTERP_STAGE_H
#define CH10_INTERP_STAGE_H

#include "05_lambert/shading_stage.h"
#include "10_interpolation/shade_interp.h"

/* Chapter 10's stage over the query `build` makes (NULL: chapter 04's
 * linear scan), its knobs' rows (in rows[MAX_STAGE_KNOBS]) and the
 * tracer's knobs aimed at *k, which the caller owns. */
shading_stage interp_stage(interp_knobs *k, knob *rows, build_query_fn build);

#endif
