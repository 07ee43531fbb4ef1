/* interp_scene.h - chapter 10: the built-in scene of the interpolation stage.
 *
 * Three coarse spheres of INTERP_SCENE_SEGMENTS x INTERP_SCENE_BANDS (80
 * triangles each, sphere_mesh.h) on a floor, every one textured with the
 * same chequered image (sphere_mesh.h's globe_texture, made in code):
 *   left    without vertex normals: shaded flat, the lecture's "geometric normals";
 *   middle  with them: "interpolated normals", the same triangles;
 *   right   with them, and a mirror: its rim shows the mirror directions that
 *           --below-surface keeps above the surface.
 * The floor is two triangles with texture coordinates from -1 to 4: the
 * RepeatTexture shows the image 5 x 5 times.
 */
#ifndef CH10_INTERP_SCENE_H
#define CH10_INTERP_SCENE_H

#include "scene.h"

#define INTERP_SCENE_SEGMENTS 8
#define INTERP_SCENE_BANDS 6

/* Fills desc (already scene_init'ed); 0, or -1 when out of memory. */
int interp_scene(scene *desc);

#endif
