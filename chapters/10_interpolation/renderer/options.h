/* options.h - chapter 10's renderer: the option rows of chapters 06-10's knobs (--normals,
 * --texture-filter, --below-surface): the program's options, which every later renderer lists before
 * its own; the values they set are the stage's.  And the scene features chapters 10 and 11 model. */
#ifndef CH10_RENDERER_OPTIONS_H
#define CH10_RENDERER_OPTIONS_H

#include "09_refraction/renderer/options.h"
#include "10_interpolation/shade_interp.h"

/* The option rows of chapters 06-10's knobs, and the tracer's knobs, aimed at *k; returns how many rows. */
int interp_knob_rows(interp_knobs *k, knob *rows, stage_knobs *aimed);

/* The scene features chapter 10 models (a shading_stage's `modelled`); chapter 11 models the same. */
#define INTERP_MODELLED                                                                                             \
    (FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS | FEATURE_RGB_NORMALS | \
     FEATURE_LIGHTS | FEATURE_SHADOWS | FEATURE_MANY_LIGHTS | FEATURE_PHONG | FEATURE_AMBIENT | FEATURE_MIRRORS |  \
     FEATURE_GLASS | FEATURE_TEXTURES | FEATURE_VERTEX_NORMALS)

#endif
