/* joined_knobs.c - a renderer whose knob rows are a family's shared rows, then the stage's own. */
#include "joined_knobs.h"

#include <stdio.h>
#include <stdlib.h>

int renderer_main_joined(const renderer *r, const knob *first, int n_first, int argc, char **argv)
{
    renderer joined = *r;
    joined.n_knobs = n_first + r->n_knobs;
    knob *rows = calloc((size_t)joined.n_knobs + 1, sizeof *rows); /* + 1: never calloc(0) */
    if (!rows) {
        fprintf(stderr, "%s: out of memory\n", r->name);
        return 2;
    }
    for (int k = 0; k < n_first; k++)
        rows[k] = first[k];
    for (int k = 0; k < r->n_knobs; k++)
        rows[n_first + k] = r->knobs[k];
    joined.knobs = rows;
    int status = renderer_main(&joined, argc, argv);
    free(rows);
    return status;
}
