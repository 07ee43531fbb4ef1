/* shade_interp.c - chapter 10: the shade function of the interpolation stage. */
#include "10_interpolation/shade_interp.h"

#include "04_many_shapes/flat_shading.h"
#include "10_interpolation/face_query.h"
#include "10_interpolation/interpolate.h"
#include "10_interpolation/sphere_uv.h"

/* The shading of the chapters before this one: chapter 09's glass, which
 * shades every other shader by chapter 08's glazed surface. */
static color shade_earlier(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    return shade_glass(tr, sp, depth, rays);
}

static const interp_knobs *knobs_of(const tracer *tr)
{
    static const interp_knobs defaults = INTERP_KNOBS_DEFAULT;
    return tr->knobs ? (const interp_knobs *)tr->knobs : &defaults;
}

/* snippet: interp_at */
interp_point interp_at(const tracer *tr, const shading_point *sp)
{
    interp_point ip = {.sp = *sp};
    const hit_record *hit = &sp->hit;
    const mesh *m;
    const mesh_face *f = face_of_hit(tr->accel, hit, &m);
    if (f) {
        ip.smooth = knobs_of(tr)->normals == NORMALS_INTERPOLATED &&
                    vertex_normal(m, f, hit->beta, hit->gamma, &ip.n_raw);
        if (ip.smooth) /* n_s in place of n, on the side the geometric normal says */
            ip.sp.n = shading_normal(ip.n_raw, sp->n);
        ip.has_uv = f->vt[0] >= 0 && f->vt[1] >= 0 && f->vt[2] >= 0;
        if (ip.has_uv)
            ip.uv = interpolate_uv(m->uvs[f->vt[0]], m->uvs[f->vt[1]], m->uvs[f->vt[2]], hit->beta, hit->gamma);
    } else {
        const scene_surface *s = &tr->desc->surfaces[hit->source];
        if (s->kind == SURFACE_SPHERE) {
            ip.has_uv = true;
            ip.uv = sphere_uv(s->center, s->radius, hit->point);
        }
    }
    return ip;
}
/* end snippet */

/* The scene the shading of a textured point sees: the scene, but with a
 * single shader, the point's own with k_d = the texture's colour; the point
 * names that shader (hit.shader = 0).  trace() passes the tracer on to every
 * deeper ray, so shade_interp gives every point the scene itself back
 * (original_scene) before it shades: the one-shader scene never outlives the
 * point it was made for. */
typedef struct {
    scene desc;
    scene_shader shader;
} textured_scene;

static const scene *original_scene(const tracer *tr)
{
    return ((const face_query *)tr->accel)->desc;
}

/* The earlier shading with tracer tr's scene replaced by `desc`.  A tracer
 * beyond the eye ray is a path_tracer (chapter 08) that carries the path's
 * weight: the copy carries it on. */
static color shade_in(const tracer *tr, const scene *desc, const shading_point *sp, int depth, uint64_t *rays)
{
    if (tr->desc == desc)
        return shade_earlier(tr, sp, depth, rays);
    path_tracer here = {.tr = *tr, .weight = path_weight(tr, depth)};
    here.tr.desc = desc;
    return shade_earlier(&here.tr, sp, depth, rays);
}

/* snippet: shade_interp */
color shade_interp(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    const scene *desc = original_scene(tr);
    const scene_shader *shader = hit_shader(desc, &sp->hit);
    interp_point ip = interp_at(tr, sp);
    if (shader->kind == SHADER_RGB_NORMALS && ip.smooth) { /* (n + 1) / 2 of the interpolated normal */
        hit_record shown = sp->hit;
        shown.normal = ip.n_raw;
        return flat_color(desc, &shown);
    }
    const interp_knobs *knobs = knobs_of(tr);
    color k_m = shader->mirror_coefficient;
    bool mirrors = shader->kind == SHADER_GLASS || k_m.r != 0 || k_m.g != 0 || k_m.b != 0;
    if (ip.smooth && mirrors && knobs->below == BELOW_FLIP) /* keep the mirror ray above the surface */
        ip.sp.n = mirror_above(ip.sp.n, sp->n, sp->v);
    if (shader->texture < 0 || !ip.has_uv)
        return shade_in(tr, desc, &ip.sp, depth, rays);
    /* k_d from the texture: the earlier shading sees a scene whose one shader is this one, textured */
    textured_scene textured = {.desc = *desc, .shader = *shader};
    textured.shader.diffuse_color = texture_lookup(&desc->textures[shader->texture], ip.uv,
                                                   (texture_filter)knobs->filter);
    textured.desc.shaders = &textured.shader;
    textured.desc.n_shaders = 1;
    ip.sp.hit.shader = 0;
    return shade_in(tr, &textured.desc, &ip.sp, depth, rays);
}
/* end snippet */
