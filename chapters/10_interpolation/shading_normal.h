/* shading_normal.h - chapter 10: the interpolated normal, and where it may not go.
 *
 * The lecture's "What to interpolate?": "surface normals, for smooth surfaces
 * approximated with meshes: use interpolated normal for shading in place of
 * actual normal" - the "shading normal" against the "geometric normal".  A
 * mesh face whose three corners have normals (vn) gets
 *
 *     n_s = normalize((1 - beta - gamma) n_a + beta n_b + gamma n_c)
 *
 * and the shading of chapters 05-09 uses n_s wherever it used n.  The
 * geometric normal n_g keeps its two jobs: it decides which side of the
 * surface the viewer is on (n_s is turned to that side: n_s . n_g >= 0 with
 * n_g towards the viewer, whatever way the file winds the face), and it says
 * where secondary rays start (chapter 06's spawn_ray moves the origin along
 * n_g).
 *
 * A smooth normal on a coarse mesh tilts away from the flat face, most near
 * the silhouette, and there the mirror direction about n_s,
 *
 *     r = 2 (n_s . v) n_s - v,
 *
 * can point below the geometric surface (r . n_g < 0): into the object.  A
 * mirror ray sent there starts on the inside (spawn_ray puts it on r's side)
 * and finds the object's own back faces: black speckles along the rim.  The
 * chapter's answer (--below-surface=flip, the default): such an r is
 * mirrored back above the surface's plane,
 *
 *     r' = r - 2 (r . n_g) n_g,
 *
 * and the shading normal of a mirror or glass point becomes the half vector
 * of v and r',  n' = normalize(v + r'),  which is the normal about which v
 * reflects to r' exactly.  So chapters 08 and 09 need no change: they
 * reflect about n' and get r'.  r' = r where r just grazes the surface, so
 * nothing jumps from one pixel to the next.  --below-surface=keep traces r
 * as it is, for the figure that shows the speckles.
 */
#ifndef CH10_SHADING_NORMAL_H
#define CH10_SHADING_NORMAL_H

#include <stdbool.h>

#include "mesh.h"
#include "vec3.h"

typedef enum { NORMALS_INTERPOLATED, NORMALS_GEOMETRIC } normal_source;

/* The names of the sources, in enum order, NULL-terminated: the choices of
 * --normals (geometric: the mesh's vn are ignored, for the lecture's pair). */
extern const char *const normal_source_names[];

typedef enum { BELOW_FLIP, BELOW_KEEP } below_policy;

/* The names of the policies, in enum order, NULL-terminated: the choices of --below-surface. */
extern const char *const below_policy_names[];

/* The interpolated unit normal of face f of mesh m at (beta, gamma): true
 * and *n set when all three corners have normals and their blend is not the
 * zero vector (opposite corner normals); false otherwise (the face is then
 * shaded flat). */
bool vertex_normal(const mesh *m, const mesh_face *f, real beta, real gamma, vec3 *n);

/* The shading normal n_s turned to the viewer's side of the geometric
 * surface: n_s, or -n_s when n_s . n_g < 0 (n_g: the geometric unit normal
 * already turned towards the viewer). */
vec3 shading_normal(vec3 n_s, vec3 n_g);

/* The normal a mirror or glass point is shaded with so that its mirror
 * direction stays above the geometric surface: n_s itself when
 * r = 2 (n_s . v) n_s - v has r . n_g >= 0, else normalize(v + r') with
 * r' = r - 2 (r . n_g) n_g.  n_s, n_g (towards the viewer) and v are unit
 * vectors with v . n_g >= 0. */
vec3 mirror_above(vec3 n_s, vec3 n_g, vec3 v);

#endif
