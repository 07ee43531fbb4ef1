/* threads.h - the render loop's threads, each on a processor of its own.
 *
 * On Linux a new or woken thread may be queued on the processor of the
 * thread that started it, behind that thread, which spins at the OpenMP
 * barrier: it then waits for the scheduler's next tick (4 ms on a 250 Hz
 * kernel) before it runs.  On a 2-core machine a render of 0.02 s on two
 * threads took 0.010 to 0.026 s that way.  Binding each thread of the team
 * to its own processor once, before the first row, removes the wait
 * (chapters/11_grid/lab/speed7.md measures it).
 */
#ifndef RT_THREADS_H
#define RT_THREADS_H

/* Starts the OpenMP team of `threads` threads and binds its k-th thread to
 * the k-th processor this process may run on; returns when every thread is
 * bound.  Does nothing for one thread, when the process may run on fewer
 * processors than `threads`, when the environment already chooses a
 * binding (OMP_PROC_BIND or OMP_PLACES), or off Linux.  The binding holds
 * for the rest of the process: later teams of as many threads reuse it, and
 * a team of another size is bound again, over the processors the process
 * could run on at the first call.  Call it from outside parallel regions. */
void threads_bind(int threads);

#endif
