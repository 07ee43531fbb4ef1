/* panels.c - puts images side by side, each under a label, into one PNG.
 *
 *     panels [--rows N] OUTPUT.png IMAGE LABEL [IMAGE LABEL ...]
 *
 * The images must have the same height.  With --rows N they are laid out in
 * N rows of as many as it takes (the first rows full), each row centred and
 * rows 16 pixels apart (a long strip made fit for a slide); else in one row.
 * Each gets a white strip above it
 * with its LABEL centred, in the 5 x 7 bitmap font of font5x7.h (black), scaled
 * by the largest whole factor up to 3 at which every label fits its panel;
 * panels are 16 pixels apart.  Used by tools/figures.sh for the `panels`
 * lines of a chapter's figures.txt (docs/CONTRIBUTING.md).  The output is a
 * function of the inputs alone, so figures stay byte-reproducible.
 *
 * Exit status: 0, or 1 with one line naming the problem (no output written).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include "font5x7.h"

enum { GAP = 16, MAX_SCALE = 3 };

typedef struct {
    unsigned char *pixels; /* RGB, top row first */
    int width, height;
    const char *label, *path;
} panel;

/* A glyph is 5 columns and 1 of space: 6 columns a character. */
static int text_width(const char *s, int scale) { return ((int)strlen(s) * 6 - 1) * scale; }

static void put(unsigned char *img, int width, int x, int y, unsigned char value)
{
    unsigned char *p = img + 3 * ((size_t)y * (size_t)width + (size_t)x);
    p[0] = p[1] = p[2] = value;
}

static void draw_text(unsigned char *img, int width, int x0, int y0, const char *s, int scale)
{
    for (int k = 0; s[k]; k++)
        for (int row = 0; row < 9; row++)
            for (int col = 0; col < 5; col++) {
                if (!font5x7_ink(s[k], row, col))
                    continue;
                for (int a = 0; a < scale; a++)
                    for (int b = 0; b < scale; b++)
                        put(img, width, x0 + (6 * k + col) * scale + b, y0 + row * scale + a, 0);
            }
}

int main(int argc, char **argv)
{
    const char *program = argv[0];
    int rows = 1;
    if (argc > 2 && strcmp(argv[1], "--rows") == 0) {
        char *end;
        long r = strtol(argv[2], &end, 10);
        if (*end != '\0' || r < 1 || r > 64) {
            fprintf(stderr, "panels: --rows %s: give a number of rows from 1 to 64\n", argv[2]);
            return 2;
        }
        rows = (int)r;
        argc -= 2;
        argv += 2;
    }
    if (argc < 4 || argc % 2 != 0) {
        fprintf(stderr, "usage: %s [--rows N] OUTPUT.png IMAGE LABEL [IMAGE LABEL ...]\n", program);
        return 2;
    }
    const char *output = argv[1];
    int n = (argc - 2) / 2, status = 1;
    if (rows > n)
        rows = n;
    const int per_row = (n + rows - 1) / rows;
    panel *panels = calloc((size_t)n, sizeof *panels);
    unsigned char *out = NULL;
    if (!panels) {
        fprintf(stderr, "panels: out of memory\n");
        return 1;
    }
    int total = 0, height = 0, scale = MAX_SCALE, row_width = 0;
    for (int k = 0; k < n; k++) {
        panel *p = &panels[k];
        p->path = argv[2 + 2 * k];
        p->label = argv[3 + 2 * k];
        int channels;
        p->pixels = stbi_load(p->path, &p->width, &p->height, &channels, 3);
        if (!p->pixels) {
            fprintf(stderr, "panels: %s: cannot read the image (%s)\n", p->path, stbi_failure_reason());
            goto done;
        }
        if (k > 0 && p->height != height) {
            fprintf(stderr, "panels: %s is %d pixels high, %s %d: panels must have the same height\n", p->path,
                    p->height, panels[0].path, height);
            goto done;
        }
        height = p->height;
        row_width = k % per_row == 0 ? p->width : row_width + GAP + p->width;
        if (row_width > total)
            total = row_width;
        while (scale > 1 && text_width(p->label, scale) > p->width)
            scale--;
        if (text_width(p->label, scale) > p->width) {
            fprintf(stderr, "panels: the label '%s' is wider than its image %s (%d pixels)\n", p->label, p->path,
                    p->width);
            goto done;
        }
    }
    const int strip = 9 * scale + 2 * 3 * scale; /* the label's cell, with a margin of 3 font pixels around */
    rows = (n + per_row - 1) / per_row;
    const int full = rows * (strip + height) + (rows - 1) * GAP;
    out = malloc((size_t)total * (size_t)full * 3);
    if (!out) {
        fprintf(stderr, "panels: out of memory for a %dx%d image\n", total, full);
        goto done;
    }
    memset(out, 255, (size_t)total * (size_t)full * 3);
    for (int k = 0, x = 0; k < n; x += panels[k].width + GAP, k++) {
        const panel *p = &panels[k];
        const int top = k / per_row * (strip + height + GAP);
        if (k % per_row == 0) { /* a new row, centred */
            int width = -GAP;
            for (int j = k; j < n && j < k + per_row; j++)
                width += panels[j].width + GAP;
            x = (total - width) / 2;
        }
        draw_text(out, total, x + (p->width - text_width(p->label, scale)) / 2, top + 3 * scale, p->label, scale);
        for (int y = 0; y < p->height; y++)
            memcpy(out + 3 * ((size_t)(top + strip + y) * (size_t)total + (size_t)x),
                   p->pixels + 3 * (size_t)y * (size_t)p->width, 3 * (size_t)p->width);
    }
    if (!stbi_write_png(output, total, full, 3, out, total * 3)) {
        fprintf(stderr, "panels: %s: cannot write the image\n", output);
        remove(output);
        goto done;
    }
    status = 0;
done:
    for (int k = 0; k < n; k++)
        stbi_image_free(panels[k].pixels);
    free(panels);
    free(out);
    return status;
}
