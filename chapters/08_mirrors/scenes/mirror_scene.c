/* mirror_scene.c - chapter 08: the built-in scene of the mirror stage. */
#include "08_mirrors/scenes/mirror_scene.h"

#include "05_lambert/scenes/shading_scene.h"

int mirror_scene(scene *desc)
{
    if (shading_scene(desc) != 0)
        return -1;
    /* shading_scene's first surface is the floor, its last the small white sphere */
    scene_shader *floor = &desc->shaders[desc->surfaces[0].shader];
    floor->mirror_coefficient = color_make(MIRROR_SCENE_FLOOR_KM, MIRROR_SCENE_FLOOR_KM, MIRROR_SCENE_FLOOR_KM);
    scene_shader *ball = &desc->shaders[desc->surfaces[desc->n_surfaces - 1].shader];
    ball->diffuse_color = color_make((real)0.02, (real)0.02, (real)0.02); /* nearly all mirror */
    ball->mirror_coefficient = color_make(MIRROR_SCENE_BALL_KM, MIRROR_SCENE_BALL_KM, MIRROR_SCENE_BALL_KM);
    return 0;
}
