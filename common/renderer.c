#include "renderer.h"

#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "exercise.h"
#include "explain.h"
#include "png_write.h"
#include "scene_cost.h"
#include "threads.h"

int renderer_main(const renderer *r, int argc, char **argv)
{
    /* An unfinished exercise's stub (a student's build) is named once, in
     * one line after the image, however many run. */
    exercise_defer();
    char fallback[256];
    snprintf(fallback, sizeof fallback, "%s.png", r->name);
    render_options opt;
    switch (options_parse(argc, argv, r->summary, fallback, r->knobs, r->n_knobs, &opt, stdout, stderr)) {
    case OPTIONS_EXIT: return 0;
    case OPTIONS_ERROR: return 2;
    case OPTIONS_OK: break;
    }
    /* The render's threads, started and bound while the scene is read (threads.h) */
    threads_bind(opt.threads > 0 ? opt.threads : omp_get_max_threads());

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

    if (opt.explain && (opt.explain_x >= width || opt.explain_y >= height)) {
        fprintf(stderr, "%s: --explain %d,%d: no such pixel in a %dx%d image (X from 0 to %d, Y from 0 to %d)\n",
                r->name, opt.explain_x, opt.explain_y, width, height, width - 1, height - 1);
        scene_free(&desc);
        return 2;
    }

    void *prepared = r->prepare(r->context, &desc, err, sizeof err);
    if (!prepared) {
        fprintf(stderr, "%s: %s\n", r->name, err);
        scene_free(&desc);
        exercise_report(stderr, r->name); /* a stub may be why */
        return 1;
    }
    if (opt.scene_path && !opt.quiet) {
        char ignored[512];
        scene_ignored_features(scene_features(&desc), r->modelled, ignored, sizeof ignored);
        if (ignored[0])
            fprintf(stderr, "%s: %s: %s\n", r->name, opt.scene_path, ignored);
    }
    if (!r->accelerated && !opt.quiet) {
        char note[256];
        scene_cost_note(&desc, r->modelled, note, sizeof note);
        if (note[0])
            fprintf(stderr, "%s: %s: %s\n", r->name, scene_name(&desc), note);
    }

    const char *output = options_output(&opt, fallback);
    int status = 1;
    image img = {0};
    if (png_check_output(output, err, sizeof err) != 0 || /* before rendering, not after */
        (opt.explain_json && png_check_output(opt.explain_json, err, sizeof err) != 0) ||
        (opt.explain_picture && png_check_output(opt.explain_picture, err, sizeof err) != 0)) {
        fprintf(stderr, "%s: %s\n", r->name, err);
    } else if (image_init(&img, width, height) != 0) {
        fprintf(stderr, "%s: out of memory for a %dx%d image\n", r->name, width, height);
    } else {
        render_stats stats = render_image_mapped(&img, r->sample, prepared, &opt, r->pixel_to_image);
        if (stats.nonfinite > 0 && opt.nonfinite == NONFINITE_FAIL) {
            fprintf(stderr, "%s: %llu samples were NaN or infinite (--nonfinite=fail): no image written\n", r->name,
                    (unsigned long long)stats.nonfinite);
            status = 3;
        } else if (png_write(&img, desc.exposure, output, err, sizeof err) != 0) {
            fprintf(stderr, "%s: %s\n", r->name, err);
        } else {
            render_summary(stderr, r->name, &img, &opt, stats, output);
            if (stats.nonfinite > 0 && opt.quiet) /* without -q, the summary line says it */
                fprintf(stderr, "%s: %llu samples were NaN or infinite (see --nonfinite)\n", r->name,
                        (unsigned long long)stats.nonfinite);
            if (r->report && !opt.quiet)
                r->report(prepared, stats, stderr);
            status = 0;
            if (opt.explain && explain_pixel(r->sample, prepared, &opt, r->pixel_to_image, &img, &desc, stdout, err,
                                             sizeof err) != 0) {
                fprintf(stderr, "%s: %s\n", r->name, err);
                status = 1;
            }
        }
        image_free(&img);
    }
    r->release(prepared);
    scene_free(&desc);
    exercise_report(stderr, r->name);
    return status;
}
