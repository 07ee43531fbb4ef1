/* ray_view.h - chapter 01: what the renderer shows of an eye ray, and its built-in scene.
 *
 * Nothing is intersected yet, so the picture shows the rays themselves:
 * their direction, or where they meet a floor.
 */
#ifndef CH01_RAY_VIEW_H
#define CH01_RAY_VIEW_H

#include "ray.h"
#include "scene.h"

/* The ray's direction as RGB: (d/|d| + 1) / 2. */
color direction_color(ray r);

/* A checkerboard where the ray crosses the plane y = 0 (t = -p_y / d_y),
 * sky above the horizon: perspective makes the squares shrink with
 * distance, orthographic keeps them the same size. */
color floor_color(ray r);

/* A camera 2 units above the floor, looking ahead and down, with a wide
 * view; always 0. */
int ray_view_scene(scene *desc);

#endif
