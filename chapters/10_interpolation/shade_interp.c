/* shade_interp.c - chapter 10: the shade function of the interpolation stage. */
#include "10_interpolation/shade_interp.h"

#include "04_many_shapes/flat_shading.h"
#include "10_interpolation/interpolate.h"
#include "explain.h"
#include "surface_attributes.h"

const char *const texture_filter_names[] = {"nearest", "bilinear", NULL};

static const interp_knobs *knobs_of(const tracer *tr)
{
    static const interp_knobs defaults = INTERP_KNOBS_DEFAULT;
    return tr->knobs.interp ? tr->knobs.interp : &defaults;
}

/* The shading point with the interpolated normal, and its texture coordinates if it has them. */
typedef struct {
    shading_point sp;
    bool smooth;     /* sp.n is an interpolated normal */
    vec3 n_raw;      /* the interpolated normal before it was turned (RGBNormals shows it) */
    bool has_uv;
    mesh_uv uv;
} interp_point;

/* The interpolated attributes of the point sp (a surface without one keeps what it had). */
static interp_point interp_at(const tracer *tr, const shading_point *sp)
{
    interp_point ip = {.sp = *sp};
    const hit_record *hit = &sp->hit;
    const mesh *m;
    const mesh_face *f = surface_mesh_face(tr->desc, hit->source, hit->face, &m); /* the face chapter 04 records */
    if (f) {
        ip.smooth = knobs_of(tr)->normals == NORMALS_INTERPOLATED &&
                    vertex_normal(m, f, hit->beta, hit->gamma, &ip.n_raw);
        if (ip.smooth) /* n_s in place of n, on the side the geometric normal says */
            ip.sp.n = shading_normal(ip.n_raw, sp->n);
        ip.has_uv = f->vt[0] >= 0 && f->vt[1] >= 0 && f->vt[2] >= 0;
        if (ip.has_uv)
            ip.uv = interpolate_uv(m->uvs[f->vt[0]], m->uvs[f->vt[1]], m->uvs[f->vt[2]], hit->beta, hit->gamma);
    } else {
        ip.has_uv = surface_sphere_uv(tr->desc, hit->source, hit->point, &ip.uv);
    }
    return ip;
}

color shade_interp(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    const scene_shader *shader = sp->shader;
    interp_point ip = interp_at(tr, sp);
    EXPLAIN(explain_interp(sp->hit.source, sp->hit.beta, sp->hit.gamma, ip.smooth, ip.sp.n, ip.has_uv, ip.uv.u, ip.uv.v));
    if (shader->kind == SHADER_RGB_NORMALS && ip.smooth) { /* (n + 1) / 2 of the interpolated normal */
        hit_record shown = sp->hit;
        shown.normal = ip.n_raw;
        return flat_color(tr->desc, &shown);
    }
    const interp_knobs *knobs = knobs_of(tr);
    color k_m = shader->mirror_coefficient;
    bool mirrors = shader->kind == SHADER_GLASS || k_m.r != 0 || k_m.g != 0 || k_m.b != 0;
    if (ip.smooth && mirrors && knobs->below == BELOW_FLIP) /* keep the mirror ray above the surface */
        ip.sp.n = mirror_above(ip.sp.n, sp->n, sp->v);
    if (shader->texture < 0 || !ip.has_uv)
        return shade_glass(tr, &ip.sp, depth, rays);
    /* k_d from the texture: the earlier shading is given the point's shader with that k_d */
    scene_shader textured = *shader;
    textured.diffuse_color = texture_lookup(&tr->desc->textures[shader->texture], ip.uv,
                                            (texture_filter)knobs->filter);
    EXPLAIN(explain_texel(ip.uv.u, ip.uv.v, texture_filter_names[knobs->filter], textured.diffuse_color));
    ip.sp.shader = &textured;
    return shade_glass(tr, &ip.sp, depth, rays);
}
