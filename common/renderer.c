#include "renderer.h"

#include <stdio.h>
#include <stdlib.h>

#include "png_write.h"

int renderer_main(const renderer *r, int argc, char **argv)
{
    render_options opt;
    switch (options_parse(argc, argv, r->summary, r->knobs, r->n_knobs, &opt, stdout, stderr)) {
    case OPTIONS_EXIT: return 0;
    case OPTIONS_ERROR: return 2;
    case OPTIONS_OK: break;
    }

    char err[1024];
    scene desc;
    if (opt.scene_path) {
        if (scene_load(opt.scene_path, &desc, err, sizeof err) != 0) {
            fprintf(stderr, "%s: %s\n", r->name, err);
            return 1;
        }
    } else {
        scene_init(&desc);
        if (r->builtin(&desc) != 0) {
            fprintf(stderr, "%s: out of memory building the built-in scene\n", r->name);
            scene_free(&desc);
            return 1;
        }
    }
    /* Size and samples: the command line, else the scene, else the defaults. */
    int width = opt.width ? opt.width : desc.width ? desc.width : r->default_width;
    int height = opt.width ? opt.height : desc.height ? desc.height : r->default_height;
    if (!opt.samples)
        opt.samples = desc.samples ? desc.samples : 1;

    void *prepared = r->prepare(&desc, err, sizeof err);
    if (!prepared) {
        fprintf(stderr, "%s: %s\n", r->name, err);
        scene_free(&desc);
        return 1;
    }
    if (opt.scene_path && !opt.quiet) {
        char ignored[512];
        scene_ignored_features(scene_features(&desc), r->modelled, ignored, sizeof ignored);
        if (ignored[0])
            fprintf(stderr, "%s: %s: %s\n", r->name, opt.scene_path, ignored);
    }

    char fallback[256];
    snprintf(fallback, sizeof fallback, "%s.png", r->name);
    const char *output = options_output(&opt, fallback);
    int status = 1;
    image img;
    if (image_init(&img, width, height) != 0) {
        fprintf(stderr, "%s: out of memory for a %dx%d image\n", r->name, width, height);
    } else {
        render_stats stats = render_image_mapped(&img, r->sample, prepared, &opt, r->pixel_to_image);
        if (png_write(&img, desc.exposure, output, err, sizeof err) != 0) {
            fprintf(stderr, "%s: %s\n", r->name, err);
        } else {
            render_summary(stderr, r->name, &img, &opt, stats, output);
            status = 0;
        }
        image_free(&img);
    }
    r->release(prepared);
    scene_free(&desc);
    return status;
}
