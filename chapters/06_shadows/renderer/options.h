/* options.h - chapter 06's renderer: the option rows of chapter 06's knob (--shadow-eps): the program's
 * options, which every later renderer lists before its own; the values they set are the stage's. */
#ifndef CH06_RENDERER_OPTIONS_H
#define CH06_RENDERER_OPTIONS_H

#include "06_shadows/spawn.h"

/* The option rows of chapter 06's knobs, aimed at *k, into rows[], and the
 * tracer's knobs at *k too; returns how many rows (every later stage lists
 * them through its own rows function). */
int spawn_knob_rows(spawn_knobs *k, knob *rows, stage_knobs *aimed);

#endif
