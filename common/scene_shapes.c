/* scene_shapes.c - the spheres and triangles that the surfaces of a scene file stand for. */
#include "scene_shapes.h"

#include <stdio.h>

/* Component k (0 = x, 1 = y, 2 = z) of a vector, and setting it. */
static real get(vec3 a, int k) { return k == 0 ? a.x : k == 1 ? a.y : a.z; }
static void set(vec3 *a, int k, real value) { *(k == 0 ? &a->x : k == 1 ? &a->y : &a->z) = value; }

static void corners(vec3 out[3], vec3 a, vec3 b, vec3 c)
{
    out[0] = a;
    out[1] = b;
    out[2] = c;
}

void box_triangles(vec3 min_pt, vec3 max_pt, vec3 out[BOX_TRIANGLES][3])
{
    /* The face perpendicular to axis a spans the two other axes, taken in
     * cyclic order (a+1, a+2) so that e_(a+1) x e_(a+2) = e_a.  Its corners
     * q00, q10, q11, q01 (q10 is one step along a+1) go round counter-clockwise
     * seen from +a: the +a face uses them in that order, the -a face in the
     * reverse order, and both normals point out of the box. */
    for (int a = 0; a < 3; a++) {
        int i = (a + 1) % 3, j = (a + 2) % 3;
        for (int side = 0; side < 2; side++) {
            vec3 q00 = min_pt; /* on the face: coordinate a is min or max */
            set(&q00, a, get(side ? max_pt : min_pt, a));
            vec3 q10 = q00, q01 = q00;
            set(&q10, i, get(max_pt, i));
            set(&q01, j, get(max_pt, j));
            vec3 q11 = q10;
            set(&q11, j, get(max_pt, j));
            vec3(*face)[3] = &out[2 * (2 * a + side)];
            if (side) { /* +a: counter-clockwise seen from +a */
                corners(face[0], q00, q10, q11);
                corners(face[1], q00, q11, q01);
            } else { /* -a: counter-clockwise seen from -a */
                corners(face[0], q00, q11, q10);
                corners(face[1], q00, q01, q11);
            }
        }
    }
}

/* The shapes of scene surface k, each given to add; -1 as soon as add fails. */
static int surface_shapes(const scene *desc, int k, int (*add)(void *, const scene_shape *), void *context)
{
    const scene_surface *s = &desc->surfaces[k];
    scene_shape shape = {.shader = s->shader, .source = k};
    switch (s->kind) {
    case SURFACE_SPHERE:
        shape.is_sphere = true;
        shape.center = s->center;
        shape.radius = s->radius;
        return add(context, &shape) < 0 ? -1 : 0;
    case SURFACE_TRIANGLE:
        corners(shape.v, s->v0, s->v1, s->v2);
        return add(context, &shape) < 0 ? -1 : 0;
    case SURFACE_BOX: {
        vec3 faces[BOX_TRIANGLES][3];
        box_triangles(s->min_pt, s->max_pt, faces);
        for (shape.face = 0; shape.face < BOX_TRIANGLES; shape.face++) {
            corners(shape.v, faces[shape.face][0], faces[shape.face][1], faces[shape.face][2]);
            if (add(context, &shape) < 0)
                return -1;
        }
        return 0;
    }
    case SURFACE_MESH: {
        const mesh *m = &desc->meshes[s->mesh];
        for (shape.face = 0; shape.face < m->n_faces; shape.face++) {
            const int *v = m->faces[shape.face].v;
            corners(shape.v, m->positions[v[0]], m->positions[v[1]], m->positions[v[2]]);
            if (add(context, &shape) < 0)
                return -1;
        }
        return 0;
    }
    }
    return 0;
}

int scene_shapes(const scene *desc, int (*add)(void *context, const scene_shape *shape), void *context, char *err,
                 size_t err_size)
{
    for (int k = 0; k < desc->n_surfaces; k++) {
        if (surface_shapes(desc, k, add, context) != 0) {
            snprintf(err, err_size, "%s:%d: out of memory for the surface list", scene_name(desc),
                     desc->surfaces[k].line);
            return -1;
        }
    }
    return 0;
}
