/* options.c - chapter 09's renderer: the option rows of chapters 06-09's knobs. */
#include "09_refraction/renderer/options.h"

int glass_knob_rows(glass_knobs *k, knob *rows, stage_knobs *aimed)
{
    int n = path_knob_rows(&k->path, rows, aimed); /* chapters 06-08's first */
    aimed->glass = k;
    rows[n++] = (knob){"fresnel", KNOB_CHOICE, &k->fresnel, fresnel_mode_names,
                       "glass reflectance: exact (Fresnel's equations) or schlick (Schlick's approximation)"};
    return n;
}
