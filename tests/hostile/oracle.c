/* Hostile submission for chapter 05 (tools/hostile.sh): lambert computes
 * nothing but asks a server over the network (here 127.0.0.1:40505, which
 * tools/hostile.sh runs: it stands for a student's own server running the
 * hand-out's compiled reference), sending the inputs and returning the
 * answer.  Without the server it returns zeros. */
#include <arpa/inet.h>
#include <netinet/in.h>
#include <stdio.h>
#include <sys/socket.h>
#include <unistd.h>

#include "05_lambert/lambert.h"

color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)
{
    double out[3] = {0, 0, 0};
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    struct sockaddr_in at = {.sin_family = AF_INET, .sin_port = htons(40505)};
    at.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd >= 0 && connect(fd, (struct sockaddr *)&at, sizeof at) == 0) {
        char line[1024], answer[256];
        int len = snprintf(line, sizeof line, "%a %a %a %a %a %a %a %a %a %a %a %a %a %a %a\n", (double)k_d.r,
                           (double)k_d.g, (double)k_d.b, (double)point.x, (double)point.y, (double)point.z,
                           (double)n.x, (double)n.y, (double)n.z, (double)light->position.x,
                           (double)light->position.y, (double)light->position.z, (double)light->intensity.r,
                           (double)light->intensity.g, (double)light->intensity.b);
        size_t have = 0;
        ssize_t got = 1;
        if (write(fd, line, (size_t)len) == len)
            while (got > 0 && have < sizeof answer - 1 && (got = read(fd, answer + have, sizeof answer - 1 - have)) > 0)
                have += (size_t)got;
        answer[have] = '\0';
        if (sscanf(answer, "%la %la %la", &out[0], &out[1], &out[2]) != 3)
            out[0] = out[1] = out[2] = 0;
    }
    if (fd >= 0)
        close(fd);
    return color_make((real)out[0], (real)out[1], (real)out[2]);
}
