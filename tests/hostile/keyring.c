/* Hostile submission for chapter 05 (tools/hostile.sh): each test leaves a
 * key in the kernel's keyrings of its user (the user keyring, the user
 * session keyring and the persistent keyring), which outlive every process
 * of the user, and first says whether an earlier test left one there
 * ("litter: found ...").  Nothing must carry over from one test to the
 * next, and nothing must stay behind after grading.  lambert returns
 * zeros. */
#define _GNU_SOURCE /* syscall */
#include <linux/keyctl.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static atomic_int done; /* the suite's renders call this from several threads at once */
    if (!atomic_exchange(&done, 1)) {
        long persistent = syscall(SYS_keyctl, KEYCTL_GET_PERSISTENT, -1, KEY_SPEC_USER_KEYRING);
        const long rings[] = {KEY_SPEC_USER_KEYRING, KEY_SPEC_USER_SESSION_KEYRING, persistent};
        const char *const names[] = {"the user keyring", "the user session keyring", "the persistent keyring"};
        for (int k = 0; k < 3; k++) {
            if (rings[k] == -1)
                continue;
            long key = syscall(SYS_keyctl, KEYCTL_SEARCH, rings[k], "user", "rt-litter", 0);
            char text[64] = "";
            if (key > 0 && syscall(SYS_keyctl, KEYCTL_READ, key, text, sizeof text - 1) > 0)
                fprintf(stderr, "litter: found a key in %s from an earlier test (\"%s\")\n", names[k], text);
            syscall(SYS_add_key, "user", "rt-litter", "left by a test", strlen("left by a test"), rings[k]);
        }
    }
    return color_make(0, 0, 0);
}
