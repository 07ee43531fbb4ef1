/* renderer.h - the main() that every chapter's renderer shares.
 *
 * A chapter describes its stage in a `renderer` and calls renderer_main():
 * it parses the shared options and the chapter's knobs, loads the scene file
 * (or builds the built-in scene), lets the chapter prepare what it traces,
 * renders, writes the PNG, and prints the one-line summary.
 *
 * Exit status: 0 on success, 1 for a bad scene or an unwritable output (with
 * one line naming the file, the line and the problem), 2 for a bad option,
 * 3 when samples were NaN or infinite under --nonfinite=fail (no image).
 */
#ifndef RT_RENDERER_H
#define RT_RENDERER_H

#include <stdbool.h>

#include "options.h"
#include "render_loop.h"
#include "scene.h"

typedef struct {
    const char *name;    /* "01_camera_rays": the default output is name.png */
    const char *summary; /* first line of --help */
    const knob *knobs;
    int n_knobs;
    unsigned modelled; /* the scene_features this stage models; the rest are named as ignored */
    bool accelerated;  /* traces through an acceleration structure (chapter 11): no warning for big meshes */
    int default_width, default_height;

    /* Fills `desc` (already scene_init'ed) with the built-in scene. */
    int (*builtin)(scene *desc);
    /* Builds what the stage traces from the description, given `context`.
     * Returns NULL with "file:line: problem" in err when the description
     * cannot be rendered (a degenerate camera, say). */
    void *(*prepare)(const void *context, const scene *desc, char *err, size_t err_size);
    const void *context; /* what prepare needs of the renderer beyond its knobs (NULL: nothing) */
    sample_fn sample;
    void (*release)(void *prepared);
    /* Chapter 01's pixel_to_image; NULL: render_image_mapped's own. */
    pixel_map_fn pixel_to_image;
    /* Optional: one more line after the summary (not with -q), such as what
     * an acceleration structure cost and did. */
    void (*report)(const void *prepared, render_stats stats, FILE *out);
} renderer;

int renderer_main(const renderer *r, int argc, char **argv);

#endif
