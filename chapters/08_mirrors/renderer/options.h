/* options.h - chapter 08's renderer: the option rows of chapters 06-08's knobs (--depth, --min-weight): the program's
 * options, which every later renderer lists before its own; the values they set are the stage's. */
#ifndef CH08_RENDERER_OPTIONS_H
#define CH08_RENDERER_OPTIONS_H

#include "07_blinn_phong/renderer/options.h"
#include "08_mirrors/path.h"

/* The option rows of chapters 06-08's knobs, and the tracer's knobs, aimed
 * at *k; returns how many rows. */
int path_knob_rows(path_knobs *k, knob *rows, stage_knobs *aimed);

#endif
