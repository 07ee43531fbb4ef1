/* acne.c - chapter 06's lab: shadow acne and light leaks, measured. */
#include "06_shadows/lab/acne.h"

#include "06_shadows/shade_shadows.h"
#include "06_shadows/shadow.h"

const char *const acne_shape_names[ACNE_SHAPES] = {"square", "sphere"};
const real acne_scales[ACNE_SCALES] = {(real)1e-4, (real)1e-2, 1, (real)1e2, (real)1e4};

/* A parallelogram centred at c with half-sides a and b, as two triangles
 * whose normal is a x b. */
static int add_square(surface_list *list, vec3 c, vec3 a, vec3 b)
{
    vec3 p00 = vec3_sub(vec3_sub(c, a), b), p10 = vec3_sub(vec3_add(c, a), b);
    vec3 p11 = vec3_add(vec3_add(c, a), b), p01 = vec3_add(vec3_sub(c, a), b);
    if (surface_list_add_triangle(list, (triangle){p00, p10, p11}, -1, 0) < 0 ||
        surface_list_add_triangle(list, (triangle){p00, p11, p01}, -1, 0) < 0)
        return -1;
    return 0;
}

/* The shape alone (`bare`) and with its occluder (`covered`). */
static int build(acne_shape shape, vec3 c, real s, vec3 normal, vec3 a, vec3 b, surface_list *bare,
                 surface_list *covered)
{
    const real gap = (real)1e-4 * s;
    if (shape == ACNE_SPHERE) {
        sphere ball = {c, s / 2}, shell = {c, s / 2 + gap};
        return surface_list_add_sphere(bare, ball, -1, 0) < 0 || surface_list_add_sphere(covered, ball, -1, 0) < 0 ||
                       surface_list_add_sphere(covered, shell, -1, 0) < 0
                   ? -1
                   : 0;
    }
    /* the occluder: gap above the square, half as large again on each side */
    vec3 above = vec3_add(c, vec3_scale(normal, gap));
    return add_square(bare, c, a, b) != 0 || add_square(covered, c, a, b) != 0 ||
                   add_square(covered, above, vec3_scale(a, (real)1.5), vec3_scale(b, (real)1.5)) != 0
               ? -1
               : 0;
}

int acne_measure(acne_shape shape, real s, eps_policy policy, int n, acne_result *result)
{
    const vec3 c = vec3_scale(vec3_make((real)3.7, (real)2.9, (real)-4.3), s);
    const vec3 normal = vec3_normalize(vec3_make((real)0.3, 1, (real)0.2)); /* about 20 degrees from +y */
    const vec3 a = vec3_scale(vec3_normalize(vec3_cross(normal, vec3_make(0, 0, 1))), s / 2);
    const vec3 b = vec3_cross(vec3_scale(a, 2 / s), vec3_scale(normal, s / 2)); /* a x b along normal */
    const vec3 light = vec3_add(c, vec3_scale(vec3_make((real)0.4, (real)2.5, (real)0.3), s));
    const vec3 eye = vec3_add(c, vec3_scale(vec3_make((real)-1.5, (real)2.0, (real)2.2), s));

    surface_list bare, covered;
    surface_list_init(&bare, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    surface_list_init(&covered, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    int status = -1;
    if (build(shape, c, s, normal, a, b, &bare, &covered) != 0)
        goto done;

    const tracer open = {.closest_hit = closest_hit_linear, .accel = &bare};
    const tracer shut = {.closest_hit = closest_hit_linear, .accel = &covered};
    long points = 0, acne = 0, leak = 0;
    uint64_t rays[RAY_KINDS] = {0};
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            /* the square's points inside its border by 5 %; for the sphere
             * the same pattern, seen from the eye, covers its middle */
            real u = (real)0.9 * (((real)i + (real)0.5) / (real)n - (real)0.5) * 2;
            real v = (real)0.9 * (((real)j + (real)0.5) / (real)n - (real)0.5) * 2;
            vec3 target = vec3_add(c, vec3_add(vec3_scale(a, u), vec3_scale(b, v)));
            ray r = {eye, vec3_sub(target, eye)};
            shading_point sp = {.r = r};
            if (!closest_hit_linear(&bare, r, 0, REAL_INFINITY, &sp.hit))
                continue; /* misses the sphere's outline */
            sp.v = vec3_neg(vec3_normalize(r.d));
            sp.n = normal_towards_viewer(sp.hit.normal, r.d);
            scene_light lamp = {.position = light};
            if (!light_in_front(&sp, &lamp))
                continue; /* no shadow ray there (chapter 06's shade function casts none) */
            points++;
            acne += light_blocked(&open, &sp, light, policy, rays);
            leak += !light_blocked(&shut, &sp, light, policy, rays);
        }
    }
    *result = (acne_result){
        .points = points,
        .acne = points ? 100.0 * (double)acne / (double)points : 0,
        .leak = points ? 100.0 * (double)leak / (double)points : 0,
    };
    status = 0;
done:
    surface_list_free(&bare);
    surface_list_free(&covered);
    return status;
}
