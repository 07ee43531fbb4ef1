/* options.c - chapter 07's renderer: the option rows of chapters 06-07's knobs. */
#include "07_blinn_phong/renderer/options.h"

int phong_knob_rows(phong_knobs *k, knob *rows, stage_knobs *aimed)
{
    int n = spawn_knob_rows(&k->spawn, rows, aimed); /* chapter 06's first */
    aimed->phong = k;
    rows[n++] = (knob){"phong", KNOB_CHOICE, &k->form, phong_form_names,
                       "specular term: course k_s (n.h)^p I/r^2, lecture also times max(0, n.l)"};
    return n;
}
