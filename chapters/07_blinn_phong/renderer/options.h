/* options.h - chapter 07's renderer: the option rows of chapters 06-07's knobs (--phong): the program's
 * options, which every later renderer lists before its own; the values they set are the stage's. */
#ifndef CH07_RENDERER_OPTIONS_H
#define CH07_RENDERER_OPTIONS_H

#include "06_shadows/renderer/options.h"
#include "07_blinn_phong/shade_phong.h"

/* The option rows of chapters 06-07's knobs, and the tracer's knobs, aimed
 * at *k; returns how many rows. */
int phong_knob_rows(phong_knobs *k, knob *rows, stage_knobs *aimed);

#endif
