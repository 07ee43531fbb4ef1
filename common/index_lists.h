/* index_lists.h - lists of item indices in numbered bins, stored flat, built by a counting sort.
 *
 * Bin b lists entries[start[b]] .. entries[start[b + 1] - 1], in increasing
 * item order: no pointer and no allocation per bin.
 */
#ifndef RT_INDEX_LISTS_H
#define RT_INDEX_LISTS_H

#include <stddef.h>
#include <stdint.h>

typedef struct index_lists_fill index_lists_fill;

/* Says where item k goes: calls index_lists_put(fill, b) for every bin b that lists it. */
typedef void index_lists_place(void *ctx, long k, index_lists_fill *fill);
void index_lists_put(index_lists_fill *fill, long bin);

/* Lists items 0 .. n_items - 1 in n_bins bins, calling place twice for each
 * item (once to count, once to write; both calls must put the same bins).
 * On success *start (n_bins + 1 offsets) and *entries are the caller's to
 * free, and the number of entries is returned; else -1 with "what: problem"
 * in err (out of memory, more than 2^32 entries), and nothing is allocated. */
long index_lists_build(long n_bins, long n_items, index_lists_place *place, void *ctx, uint32_t **start,
                       uint32_t **entries, const char *what, char *err, size_t err_size);

#endif
