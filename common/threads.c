/* threads.c - the render loop's threads, each on a processor of its own (threads.h). */
#ifdef __linux__
#define _GNU_SOURCE /* sched_setaffinity, cpu_set_t */
#include <sched.h>
#endif

#include "threads.h"

#include <omp.h>
#include <stdlib.h>

void threads_bind(int threads)
{
#ifdef __linux__
    /* the processors the process may run on, read before the first binding
     * (which leaves the calling thread, whose mask new threads inherit, one) */
    static cpu_set_t allowed;
    static int allowed_known = 0; /* 1: read, -1: could not be read */
    static _Thread_local int bound; /* the team size this thread's team was bound for */
    if (!allowed_known)
        allowed_known = sched_getaffinity(0, sizeof allowed, &allowed) == 0 ? 1 : -1;
    if (threads <= 1 || bound == threads || allowed_known < 0 || getenv("OMP_PROC_BIND") || getenv("OMP_PLACES") ||
        CPU_COUNT(&allowed) < threads)
        return;
    int arrived = 0;
#pragma omp parallel num_threads(threads)
    {
        /* the k-th allowed processor for thread k */
        int k = omp_get_thread_num(), cpu = -1;
        for (int c = 0; c < CPU_SETSIZE && cpu < 0; c++)
            if (CPU_ISSET(c, &allowed) && k-- == 0)
                cpu = c;
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(cpu, &one);
        sched_setaffinity(0, sizeof one, &one);
        /* wait, yielding the processor, until every thread is on its own: a
         * thread queued behind this one runs now, not at the next tick */
        int n;
#pragma omp atomic capture
        n = ++arrived;
        while (n < threads) {
            sched_yield();
#pragma omp atomic read
            n = arrived;
        }
    }
    bound = threads;
#else
    (void)threads;
#endif
}
