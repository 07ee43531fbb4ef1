/* phong.h - chapter 07: the specular term of Blinn-Phong shading.
 *
 * The lecture's "Specular shading (Blinn-Phong)": a shiny surface is bright
 * near the mirror configuration, where the direction to the viewer v is the
 * direction to the light l reflected about n.  Close to mirror <=> the half
 * vector is close to the normal:
 *
 *     h = bisector(v, l) = (v + l) / |v + l|
 *     (cos alpha)^p = (n . h)^p
 *
 * and the larger the exponent p, the narrower the highlight.  The specular
 * radiance of one point light is
 *
 *     course:  k_s max(0, n . h)^p I / r^2                (the course's images)
 *     lecture: k_s max(0, n . h)^p max(0, n . l) I / r^2  ("modified Blinn-Phong")
 *
 * k_s is the shader's specularColor and p its exponent (docs/scenes.md).  The
 * lecture writes L_r = (R/pi + k_s (n . h)^p) max(0, n . l) I / r^2: its
 * specular term is weighted by the cosine like the diffuse one.  The course's
 * solution leaves the cosine out of the specular term; --phong chooses.
 */
#ifndef CH07_PHONG_H
#define CH07_PHONG_H

#include "color.h"
#include "scene.h"
#include "vec3.h"

typedef enum { PHONG_COURSE, PHONG_LECTURE } phong_form;

/* The names of the forms, in enum order, NULL-terminated: the choices of --phong. */
extern const char *const phong_form_names[];

/* The specular term of `light` at `point` with unit shading normal n and unit
 * vector v towards the viewer: k_s max(0, n . h)^p I / r^2, times max(0, n . l)
 * in the lecture's form, with h = (v + l) / |v + l| and p >= 0 any real. */
color blinn_phong_specular(color k_s, real p, vec3 point, vec3 n, vec3 v, const scene_light *light,
                           phong_form form);

#endif
