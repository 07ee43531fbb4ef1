/* Lists of indices in bins by counting sort: common/index_lists.h. */
#include <stdlib.h>

#include "index_lists.h"
#include "suite.h"

/* Item k goes in bins k mod 3 and (k mod 3) + 2, and items 5 and 6 nowhere. */
static void place_mod3(void *ctx, long k, index_lists_fill *fill)
{
    (void)ctx;
    if (k == 5 || k == 6)
        return;
    index_lists_put(fill, k % 3);
    index_lists_put(fill, k % 3 + 2);
}

static void test_lists(void **state)
{
    (void)state;
    uint32_t *start = NULL, *entries = NULL;
    char err[128];
    long n = index_lists_build(6, 10, place_mod3, NULL, &start, &entries, "test", err, sizeof err);
    /* 8 items in 2 bins each; bin 2 gets items 2, 8 (k mod 3 = 2) and 0, 3, 9 (k mod 3 + 2 = 2), in order */
    static const uint32_t want_start[7] = {0, 3, 6, 11, 14, 16, 16};
    static const uint32_t want[16] = {0, 3, 9, 1, 4, 7, 0, 2, 3, 8, 9, 1, 4, 7, 2, 8};
    assert_int_equal(16, n);
    for (int b = 0; b < 7; b++)
        assert_int_equal(want_start[b], start[b]);
    for (int e = 0; e < 16; e++)
        assert_int_equal(want[e], entries[e]);
    free(start);
    free(entries);
    /* no items: every bin empty, still two allocations */
    n = index_lists_build(3, 0, place_mod3, NULL, &start, &entries, "test", err, sizeof err);
    assert_int_equal(0, n);
    for (int b = 0; b < 4; b++)
        assert_int_equal(0, start[b]);
    free(start);
    free(entries);
}

static const graded_test tests[] = {
    GRADED(test_lists, 0),
};
SUITE_MAIN("common_index_lists", tests)
