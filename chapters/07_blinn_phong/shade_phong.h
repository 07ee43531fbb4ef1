/* shade_phong.h - chapter 07: the shade function of the Blinn-Phong stage.
 *
 * The lecture's "Multiple lights" and "Ambient shading":
 *
 *     shade(ray, point, normal, lights)
 *         result = ambient
 *         for light in lights
 *             if (shadow ray not blocked)
 *                 result += shading contribution
 *         return result
 *
 * The contribution of one light is chapter 05's Lambert term, plus the
 * specular term (phong.h) for a Phong shader.  The ambient term is the
 * scene's <ambient> radiance, added as it is (docs/scenes.md); black when the
 * scene has none, as in the course's scenes.
 */
#ifndef CH07_SHADE_PHONG_H
#define CH07_SHADE_PHONG_H

#include "06_shadows/spawn.h"
#include "07_blinn_phong/phong.h"

/* snippet: phong_knobs */
/* The knobs of chapter 07: chapter 06's, then its own. */
typedef struct phong_knobs {
    spawn_knobs spawn;
    int form; /* a phong_form: --phong */
} phong_knobs;
/* end snippet */

/* The defaults, an initializer: chapter 06's, and the course's form. */
#define PHONG_KNOBS_DEFAULT {.spawn = SPAWN_KNOBS_DEFAULT, .form = PHONG_COURSE}

/* The form of a tracer with chapter 07's knobs; the course's without. */
phong_form tracer_phong_form(const tracer *tr);

/* The light one unblocked `light` sends from sp towards the viewer: the
 * Lambert term, plus the specular term for a Phong shader. */
color light_contribution(const tracer *tr, const shading_point *sp, const scene_shader *shader,
                         const scene_light *light);

/* A shade_fn: ambient plus every unblocked light's contribution.  Shadow
 * rays only towards lights in front of the surface (n . l > 0). */
color shade_phong(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays);

#endif
