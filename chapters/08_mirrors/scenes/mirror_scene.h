/* mirror_scene.h - chapter 08: the built-in scene of the mirror stage.
 *
 * The built-in scene of chapters 05-07 (shading_scene.h) with the lecture's
 * "glazed material on floor": the floor keeps its diffuse colour and gets a
 * mirror coefficient, and the small white sphere in front becomes a mirror
 * ball.  The same scene, so that chapter 07's image and this one can be put
 * side by side.
 */
#ifndef CH08_MIRROR_SCENE_H
#define CH08_MIRROR_SCENE_H

#include "scene.h"

/* The floor's k_m and the ball's. */
#define MIRROR_SCENE_FLOOR_KM ((real)0.3)
#define MIRROR_SCENE_BALL_KM ((real)0.8)

/* Fills desc (already scene_init'ed); 0, or -1 when out of memory. */
int mirror_scene(scene *desc);

#endif
