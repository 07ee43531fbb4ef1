/* shapes_stage.h - chapter 04: what its renderer traces.
 *
 * The camera, the surface list built with the formula and test that
 * --sphere and --triangle chose (shape_knobs.h), and the scene description,
 * whose shaders and backColor give the colours.
 */
#ifndef CH04_SHAPES_STAGE_H
#define CH04_SHAPES_STAGE_H

#include "01_camera_rays/camera.h"
#include "04_many_shapes/surface.h"
#include "scene.h"

typedef struct {
    camera cam;
    surface_list list;
    const scene *desc;
} shapes_stage;

/* renderer.h's prepare (its context: the renderer's shape_knobs) and release for a shapes_stage. */
void *shapes_stage_prepare(const void *context, const scene *desc, char *err, size_t err_size);
void shapes_stage_release(void *prepared);

#endif
