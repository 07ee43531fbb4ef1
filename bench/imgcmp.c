/* imgcmp.c - pixel statistics of PNG images, for the bench.
 *
 *     imgcmp A.png B.png            "SHARE MAXDIFF DIFFERING PIXELS MAE RMSE PSNR": the share of
 *                                   pixels (in %) in which any channel differs, the largest difference
 *                                   of a channel (0-255), how many pixels differ, how many there are,
 *                                   and the error as rendering papers give it, over all channels of
 *                                   all pixels in display levels (0-255): the mean absolute
 *                                   difference, the root of the mean squared difference, and the
 *                                   peak signal-to-noise ratio 20 log10(255 / RMSE) in dB ("inf"
 *                                   for equal images)
 *     imgcmp merge R.png G.png B.png OUT.png
 *                                   OUT takes its red channel from R, green from G, blue from B
 *     imgcmp size A.png             "W H"
 *
 * Exit status 0, or 1 with a message naming the file (unreadable, or sizes that differ).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image.h>
#include <stb_image_write.h>

typedef struct {
    unsigned char *px;
    int w, h;
} picture;

static int load(const char *path, picture *p)
{
    int channels;
    p->px = stbi_load(path, &p->w, &p->h, &channels, 3);
    if (!p->px) {
        fprintf(stderr, "imgcmp: %s: %s\n", path, stbi_failure_reason());
        return -1;
    }
    return 0;
}

static int same_size(const picture *a, const picture *b, const char *pa, const char *pb)
{
    if (a->w == b->w && a->h == b->h)
        return 1;
    fprintf(stderr, "imgcmp: %s is %dx%d but %s is %dx%d\n", pa, a->w, a->h, pb, b->w, b->h);
    return 0;
}

static int compare(const char *pa, const char *pb)
{
    picture a, b;
    if (load(pa, &a) != 0)
        return 1;
    if (load(pb, &b) != 0 || !same_size(&a, &b, pa, pb)) {
        stbi_image_free(a.px);
        if (b.px)
            stbi_image_free(b.px);
        return 1;
    }
    long n = (long)a.w * a.h, differing = 0;
    int max_diff = 0;
    double sum_abs = 0, sum_sq = 0; /* exact: integers far below 2^53 */
    for (long k = 0; k < n; k++) {
        int pixel_diff = 0;
        for (int c = 0; c < 3; c++) {
            int d = abs(a.px[3 * k + c] - b.px[3 * k + c]);
            sum_abs += d;
            sum_sq += (double)d * d;
            if (d > pixel_diff)
                pixel_diff = d;
        }
        differing += pixel_diff > 0;
        if (pixel_diff > max_diff)
            max_diff = pixel_diff;
    }
    double values = 3.0 * (double)n, rmse = sqrt(sum_sq / values);
    printf("%.4f %d %ld %ld %.4g %.4g ", 100.0 * (double)differing / (double)n, max_diff, differing, n,
           sum_abs / values, rmse);
    if (rmse > 0)
        printf("%.2f\n", 20 * log10(255 / rmse));
    else
        printf("inf\n");
    stbi_image_free(a.px);
    stbi_image_free(b.px);
    return 0;
}

static int merge(char **paths)
{
    picture p[3];
    int loaded = 0, status = 1;
    for (; loaded < 3; loaded++)
        if (load(paths[loaded], &p[loaded]) != 0 || (loaded && !same_size(&p[0], &p[loaded], paths[0], paths[loaded])))
            break;
    if (loaded == 3) {
        long n = (long)p[0].w * p[0].h;
        for (long k = 0; k < n; k++) {
            p[0].px[3 * k + 1] = p[1].px[3 * k + 1];
            p[0].px[3 * k + 2] = p[2].px[3 * k + 2];
        }
        if (stbi_write_png(paths[3], p[0].w, p[0].h, 3, p[0].px, p[0].w * 3))
            status = 0;
        else
            fprintf(stderr, "imgcmp: cannot write %s\n", paths[3]);
    }
    for (int k = 0; k < loaded && k < 3; k++)
        stbi_image_free(p[k].px);
    if (loaded < 3 && p[loaded].px)
        stbi_image_free(p[loaded].px);
    return status;
}

int main(int argc, char **argv)
{
    if (argc == 6 && strcmp(argv[1], "merge") == 0)
        return merge(argv + 2);
    if (argc == 3 && strcmp(argv[1], "size") == 0) {
        picture p;
        if (load(argv[2], &p) != 0)
            return 1;
        printf("%d %d\n", p.w, p.h);
        stbi_image_free(p.px);
        return 0;
    }
    if (argc == 3)
        return compare(argv[1], argv[2]);
    fprintf(stderr, "usage: imgcmp A.png B.png | imgcmp merge R.png G.png B.png OUT.png | imgcmp size A.png\n");
    return 2;
}
