/* joined_knobs.h - a renderer whose knob rows are the rows a family of stages shares, then the stage's
 * own (the shading renderers of chapters 05-11: --sphere and --triangle before each stage's knobs). */
#ifndef RT_JOINED_KNOBS_H
#define RT_JOINED_KNOBS_H

#include "renderer.h"

/* renderer_main(r, argc, argv) with the n_first rows `first` listed before r's own knobs;
 * 2, with a message, when out of memory. */
int renderer_main_joined(const renderer *r, const knob *first, int n_first, int argc, char **argv);

#endif
