/* options.h - chapter 09's renderer: the option rows of chapters 06-09's knobs (--fresnel): the program's
 * options, which every later renderer lists before its own; the values they set are the stage's. */
#ifndef CH09_RENDERER_OPTIONS_H
#define CH09_RENDERER_OPTIONS_H

#include "08_mirrors/renderer/options.h"
#include "09_refraction/shade_glass.h"

/* The option rows of chapters 06-09's knobs, and the tracer's knobs, aimed
 * at *k; returns how many rows. */
int glass_knob_rows(glass_knobs *k, knob *rows, stage_knobs *aimed);

#endif
