/* index_lists.c - lists of item indices in numbered bins, by a counting sort. */
#include "index_lists.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct index_lists_fill {
    uint32_t *count;   /* first pass: each bin's count; second: where its next entry goes */
    uint32_t *entries; /* NULL in the first pass */
    uint32_t item;
};

void index_lists_put(index_lists_fill *fill, long bin)
{
    if (fill->entries)
        fill->entries[fill->count[bin]++] = fill->item;
    else
        fill->count[bin]++;
}

static void place_all(long n_items, index_lists_place *place, void *ctx, index_lists_fill *fill)
{
    for (long k = 0; k < n_items; k++) {
        fill->item = (uint32_t)k;
        place(ctx, k, fill);
    }
}

long index_lists_build(long n_bins, long n_items, index_lists_place *place, void *ctx, uint32_t **start,
                       uint32_t **entries, const char *what, char *err, size_t err_size)
{
    index_lists_fill fill = {.count = calloc((size_t)n_bins + 1, sizeof(uint32_t))};
    uint32_t *first = malloc(((size_t)n_bins + 1) * sizeof *first), *out = NULL;
    if (!fill.count || !first)
        goto out_of_memory;
    place_all(n_items, place, ctx, &fill);
    /* The offsets are the running sum of the counts. */
    uint64_t total = 0;
    for (long b = 0; b <= n_bins; b++) {
        first[b] = (uint32_t)total;
        total += b < n_bins ? fill.count[b] : 0;
        if (total > UINT32_MAX) {
            snprintf(err, err_size, "%s: more than 2^32 entries in its lists", what);
            goto fail;
        }
    }
    out = malloc((total ? (size_t)total : 1) * sizeof *out);
    if (!out)
        goto out_of_memory;
    memcpy(fill.count, first, (size_t)n_bins * sizeof *first);
    fill.entries = out;
    place_all(n_items, place, ctx, &fill);
    free(fill.count);
    *start = first;
    *entries = out;
    return (long)total;

out_of_memory:
    snprintf(err, err_size, "%s: out of memory", what);
fail:
    free(fill.count);
    free(first);
    free(out);
    return -1;
}
