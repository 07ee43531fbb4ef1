/* fast_pack.c - chapter 11's lab: the cells' lists packed for the march.
 *
 * The build writes a cell's list as records, a surface and its box's six
 * bytes each (fast_grid_entry).  The march reads all of a sifted cell's
 * boxes and then the surfaces of the few that pass; packed, a cell's list
 * is one block of three rows of 32-bit words (the surfaces, the boxes' low
 * sides, their high sides), so that the box test runs on four entries at
 * once (fast_march.c) and the block stays as compact as the records were:
 * 12 bytes an entry, in the same place. */
#include <stdlib.h>
#include <string.h>

#include "11_grid/lab/fast_boxes.h"
#include "11_grid/lab/fast_build.h"

_Static_assert(sizeof(fast_grid_entry) == 3 * sizeof(uint32_t), "a record takes the three words of its packed entry");

/* Three sides of a box (x, y, z) in one word: x | y << 8 | z << 16. */
static uint32_t sides(const uint8_t b[3]) { return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16; }

/* The lists of g packed, a box's entry made FAST_GRID_BOX + its index in `boxes` (the top grid's). */
static bool pack(fast_grid *g, const struct fast_boxes *boxes)
{
    uint32_t most = 0;
    for (long c = 0; c < g->n_cells; c++)
        most = g->start[c + 1] - g->start[c] > most ? g->start[c + 1] - g->start[c] : most;
    fast_grid_entry *copy = malloc((most ? most : 1) * sizeof *copy);
    if (!copy)
        return false;
    /* A cell's block takes the bytes its records took, so each is written
     * where they lie, from a copy of them. */
    uint32_t *lists = (uint32_t *)(void *)g->refs;
    for (long c = 0; c < g->n_cells; c++) {
        const uint32_t first = g->start[c], n = g->start[c + 1] - first;
        memcpy(copy, g->refs + first, n * sizeof *copy);
        uint32_t *surface = lists + 3 * (size_t)first, *lo = surface + n, *hi = lo + n;
        for (uint32_t q = 0; q < n; q++) {
            const uint32_t k = copy[q].surface, b = boxes && k < FAST_GRID_SUB ? boxes->of[k] : FAST_BOX_NONE;
            surface[q] = b == FAST_BOX_NONE ? k : FAST_GRID_BOX + b;
            lo[q] = sides(copy[q].box);
            hi[q] = sides(copy[q].box + 3);
        }
    }
    free(copy);
    size_t held = fast_grid_memory(g) + most * sizeof *copy;
    g->peak_bytes = held > g->peak_bytes ? held : g->peak_bytes;
    g->lists = lists;
    g->refs = NULL;
    for (long k = 0; k < g->n_subs; k++)
        if (!pack(&g->subs[k], boxes))
            return false;
    return true;
}

bool fast_grid_pack(fast_grid *g) { return pack(g, g->boxes); }
