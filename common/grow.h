/* grow.h - growing arrays by doubling. */
#ifndef RT_GROW_H
#define RT_GROW_H

#include <stdlib.h>

/* Makes *array hold at least `needed` elements of `size` bytes; *capacity
 * is the number it holds now.  Returns 0, or -1 (array unchanged) when out
 * of memory. */
static inline int grow(void **array, int *capacity, int needed, size_t size)
{
    if (needed <= *capacity)
        return 0;
    int cap = *capacity ? *capacity : 8;
    while (cap < needed)
        cap *= 2;
    void *bigger = realloc(*array, (size_t)cap * size);
    if (!bigger)
        return -1;
    *array = bigger;
    *capacity = cap;
    return 0;
}

#endif
