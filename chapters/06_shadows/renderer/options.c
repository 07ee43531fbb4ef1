/* options.c - chapter 06's renderer: the option rows of chapter 06's knob. */
#include "06_shadows/renderer/options.h"

int spawn_knob_rows(spawn_knobs *k, knob *rows, stage_knobs *aimed)
{
    aimed->spawn = k;
    rows[0] = (knob){"shadow-eps", KNOB_CHOICE, &k->eps, eps_policy_names,
                     "where secondary rays start: none (the blunder), fixed 1e-3, bound (error bound)"};
    return 1;
}
