/* box.c - chapter 04: an axis-aligned box as 12 triangles. */
#include "04_many_shapes/box.h"

/* Component k (0 = x, 1 = y, 2 = z) of a vector, and setting it. */
static real get(vec3 a, int k) { return k == 0 ? a.x : k == 1 ? a.y : a.z; }
static void set(vec3 *a, int k, real value) { *(k == 0 ? &a->x : k == 1 ? &a->y : &a->z) = value; }

/* snippet: box_triangles */
void box_triangles(vec3 min_pt, vec3 max_pt, triangle out[BOX_TRIANGLES])
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
            triangle *face = &out[2 * (2 * a + side)];
            if (side) { /* +a: counter-clockwise seen from +a */
                face[0] = (triangle){q00, q10, q11};
                face[1] = (triangle){q00, q11, q01};
            } else { /* -a: counter-clockwise seen from -a */
                face[0] = (triangle){q00, q11, q10};
                face[1] = (triangle){q00, q01, q11};
            }
        }
    }
}
/* end snippet */
