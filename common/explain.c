/* explain.c - the recorder of explain.h: each report becomes a node of the tree. */
#include "explain.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "explain_tree.h"
#include "grow.h"

_Thread_local explainer *explain_now;

static const char *const kind_names[RAY_KINDS] = {"eye", "shadow", "reflected", "refracted"};

const char *explain_vec(char *buf, size_t size, vec3 a)
{
    snprintf(buf, size, "(%.6g, %.6g, %.6g)", (double)a.x, (double)a.y, (double)a.z);
    return buf;
}

const char *explain_color(char *buf, size_t size, color c)
{
    return explain_vec(buf, size, vec3_make(c.r, c.g, c.b));
}

/* A new node of `type` under the current one, its line from `format`; -1 when out of memory or full. */
static int add(explainer *e, node_type type, const char *format, ...)
{
    if (!e->failed && e->n >= EXPLAIN_MAX_NODES)
        e->failed = e->full = true;
    if (e->failed || grow((void **)&e->nodes, &e->capacity, e->n + 1, sizeof *e->nodes) != 0) {
        e->failed = true;
        return -1;
    }
    int k = e->n++;
    explain_node *node = &e->nodes[k];
    *node = (explain_node){.type = type, .parent = e->current, .first = -1, .last = -1, .next = -1,
                           .surface = -1, .tally = -1, .t_end = REAL_INFINITY};
    va_list args;
    va_start(args, format);
    vsnprintf(node->text, sizeof node->text, format, args);
    va_end(args);
    if (e->current >= 0) {
        explain_node *parent = &e->nodes[e->current];
        if (parent->last >= 0)
            e->nodes[parent->last].next = k;
        else
            parent->first = k;
        parent->last = k;
    }
    return k;
}

void explain_init(explainer *e, const scene *desc, const char *root)
{
    *e = (explainer){.current = -1, .surface = -1, .desc = desc};
    for (int d = 0; d < (int)(sizeof e->open / sizeof e->open[0]); d++)
        e->open[d] = -1;
    e->current = add(e, NODE_ROOT, "%s", root);
}

/* Shadow rays and grid cells end when something else is reported: tests go
 * into them (and a shadow ray's cells), anything else goes back to the ray
 * they belong to. */
static void close_passing(explainer *e, bool keep_shadow)
{
    while (e->current >= 0) {
        const explain_node *c = &e->nodes[e->current];
        bool shadow = c->type == NODE_RAY && c->kind == RAY_SHADOW;
        bool passing = c->type == NODE_CELL || (shadow && !keep_shadow);
        if (!passing)
            return;
        e->current = c->parent;
    }
}

/* The ray the current node belongs to. */
static explain_node *current_ray(explainer *e)
{
    for (int k = e->current; k >= 0; k = e->nodes[k].parent)
        if (e->nodes[k].type == NODE_RAY)
            return &e->nodes[k];
    return NULL;
}

/* ---- the pixel's samples ---- */

void explain_sample(int k, int n, real du, real dv, real u, real v)
{
    explainer *e = explain_now;
    while (e->current >= 0 && e->nodes[e->current].type != NODE_ROOT)
        e->current = e->nodes[e->current].parent;
    int s = add(e, NODE_SAMPLE, "sample %d of %d at (%.6g, %.6g) in the pixel: (u, v) = (%.9g, %.9g)", k + 1, n,
                (double)du, (double)dv, (double)u, (double)v);
    if (s >= 0)
        e->current = s;
    for (int d = 0; d < (int)(sizeof e->open / sizeof e->open[0]); d++)
        e->open[d] = -1;
    e->spawn[0] = '\0';
}

void explain_sample_done(color L)
{
    explainer *e = explain_now;
    while (e->current >= 0 && e->nodes[e->current].type != NODE_SAMPLE)
        e->current = e->nodes[e->current].parent;
    char c[96];
    add(e, NODE_LINE, "the sample's radiance L = %s", explain_color(c, sizeof c, L));
}

/* ---- rays and what they meet ---- */

void explain_eye_ray(ray r)
{
    explainer *e = explain_now;
    char p[96], d[96];
    int k = add(e, NODE_RAY, "eye ray p + t d: p = %s, d = %s", explain_vec(p, sizeof p, r.p),
                explain_vec(d, sizeof d, r.d));
    if (k < 0)
        return;
    e->nodes[k].kind = RAY_EYE;
    e->nodes[k].r = r;
    e->current = e->open[0] = k;
}

void explain_surface(int index, int source, int face)
{
    explain_now->surface = index;
    explain_now->source = source;
    explain_now->face = face;
}

/* "surface 3 (scene surface 1, piece 5) " of the last explain_surface, once. */
static const char *surface_label(explainer *e, char *buf, size_t size)
{
    bool pieces = e->desc && e->source >= 0 && e->source < e->desc->n_surfaces &&
                  (e->desc->surfaces[e->source].kind == SURFACE_BOX || e->desc->surfaces[e->source].kind == SURFACE_MESH);
    if (e->surface < 0)
        buf[0] = '\0';
    else if (pieces)
        snprintf(buf, size, "surface %d (scene surface %d, face %d), ", e->surface, e->source, e->face);
    else
        snprintf(buf, size, "surface %d (scene surface %d), ", e->surface, e->source);
    return buf;
}

/* A test's node: a hit is always listed, a miss while the ray (or cell) has listed fewer than EXPLAIN_MISSES_SHOWN. */
static void add_test(explainer *e, bool hit, real t, const char *format, ...)
{
    const int owner = e->current;
    if (owner < 0)
        return;
    const int order = ++e->nodes[owner].tests;
    if (!hit && e->nodes[owner].misses++ >= EXPLAIN_MISSES_SHOWN) {
        if (e->nodes[owner].hidden++ == 0) { /* the line that counts them, where they begin */
            int tally = add(e, NODE_LINE, "more misses"); /* (may move the nodes) */
            e->nodes[owner].tally = tally;
        }
        e->surface = -1;
        return;
    }
    char line[400];
    va_list args;
    va_start(args, format);
    vsnprintf(line, sizeof line, format, args);
    va_end(args);
    int k = add(e, NODE_TEST, "test %d: %s", order, line);
    if (k >= 0) {
        e->nodes[k].surface = e->surface;
        e->nodes[k].order = order;
        e->nodes[k].hit = hit;
        e->nodes[k].t = t;
    }
    e->surface = -1;
    explain_node *r = current_ray(e);
    if (hit && r && r->kind == RAY_SHADOW && (!r->blocked || t < r->t_end)) {
        r->blocked = true; /* a shadow ray is blocked by any hit: the nearest is drawn */
        r->t_end = t;
    }
}

void explain_sphere(vec3 c, real R, bool has_roots, real t0, real t1, real t_min, real t_max, bool hit, real t)
{
    explainer *e = explain_now;
    char label[96], cs[96];
    surface_label(e, label, sizeof label);
    explain_vec(cs, sizeof cs, c);
    if (hit)
        add_test(e, true, t, "%ssphere c = %s, R = %.6g: hit at t = %.9g (roots %.9g and %.9g; window (%.6g, %.6g))",
                 label, cs, (double)R, (double)t, (double)t0, (double)t1, (double)t_min, (double)t_max);
    else if (has_roots)
        add_test(e, false, 0, "%ssphere c = %s, R = %.6g: missed, its roots t = %.9g and %.9g are outside (%.6g, %.6g)",
                 label, cs, (double)R, (double)t0, (double)t1, (double)t_min, (double)t_max);
    else
        add_test(e, false, 0, "%ssphere c = %s, R = %.6g: missed, no real root (the line passes the sphere)", label, cs,
                 (double)R);
}

void explain_triangle(bool hit, real t, real beta, real gamma, real t_min, real t_max, bool line_hits, real t_line)
{
    explainer *e = explain_now;
    char label[96];
    surface_label(e, label, sizeof label);
    if (hit)
        add_test(e, true, t, "%striangle: hit at t = %.9g, beta = %.6g, gamma = %.6g (alpha = %.6g)", label, (double)t,
                 (double)beta, (double)gamma, (double)(1 - beta - gamma));
    else if (line_hits)
        add_test(e, false, 0, "%striangle: missed, the line meets it at t = %.9g, outside (%.6g, %.6g)", label,
                 (double)t_line, (double)t_min, (double)t_max);
    else
        add_test(e, false, 0, "%striangle: missed, the line passes outside it (or along its plane)", label);
}

void explain_closest(int surface, int source, real t, vec3 point)
{
    explainer *e = explain_now;
    close_passing(e, false);
    explain_node *r = current_ray(e);
    if (r)
        r->t_end = t;
    int order = 0, tests = r ? r->tests : 0; /* the last test that hit it (the grid's are in its cells) */
    for (int c = r ? r->first : -1; c >= 0; c = e->nodes[c].next)
        if (e->nodes[c].type == NODE_TEST && e->nodes[c].hit && e->nodes[c].surface == surface)
            order = e->nodes[c].order;
    char x[96], met[64] = "";
    if (order)
        snprintf(met, sizeof met, ", met in test %d of %d", order, tests);
    add(e, NODE_LINE, "closest hit: surface %d (scene surface %d)%s, t = %.9g, x = p + t d = %s", surface, source, met,
        (double)t, explain_vec(x, sizeof x, point));
}

void explain_trace(ray r, real t_min, real t_max, int depth, color weight, const uint64_t *rays)
{
    explainer *e = explain_now;
    ray_kind kind = RAY_EYE;
    for (int k = 0; k < RAY_KINDS; k++)
        if (rays[k] != e->seen[k]) {
            if (k != RAY_SHADOW)
                kind = (ray_kind)k;
            e->seen[k] = rays[k];
        }
    const int depths = (int)(sizeof e->open / sizeof e->open[0]);
    if (depth == 0 && e->open[0] >= 0) { /* the eye ray camera_ray reported */
        e->current = e->open[0];
        snprintf(e->nodes[e->current].text + strlen(e->nodes[e->current].text),
                 sizeof e->nodes[e->current].text - strlen(e->nodes[e->current].text), ", traced over t in (%.6g, %.6g)",
                 (double)t_min, (double)t_max);
        return;
    }
    if (depth > 0 && depth < depths && e->open[depth - 1] >= 0)
        e->current = e->open[depth - 1];
    close_passing(e, false);
    char p[96], d[96], w[96];
    int k = add(e, NODE_RAY, "%s ray, depth %d, path weight %s: p = %s%s%s, d = %s, t in (%.6g, %.6g)",
                kind_names[kind], depth, explain_color(w, sizeof w, weight), explain_vec(p, sizeof p, r.p),
                e->spawn[0] ? " " : "", e->spawn, explain_vec(d, sizeof d, r.d), (double)t_min, (double)t_max);
    e->spawn[0] = '\0';
    if (k < 0)
        return;
    e->nodes[k].kind = kind;
    e->nodes[k].depth = depth;
    e->nodes[k].r = r;
    e->current = k;
    if (depth < depths)
        e->open[depth] = k;
}

void explain_miss(color background)
{
    explainer *e = explain_now;
    close_passing(e, false);
    char c[96];
    add(e, NODE_LINE, "no hit: the background, %s", explain_color(c, sizeof c, background));
}

static const char *shader_name(const scene_shader *s)
{
    static const char *const names[] = {"Lambertian", "Phong", "RGBNormals", "Glass"};
    return names[s->kind];
}

void explain_shading(vec3 n_g, vec3 n, vec3 v, const scene_shader *shader)
{
    explainer *e = explain_now;
    char a[96], b[96], c[96], kd[96];
    add(e, NODE_LINE, "shading: n = %s (geometric normal %s), v = -d/|d| = %s; shader %s, k_d = %s",
        explain_vec(a, sizeof a, n), explain_vec(b, sizeof b, n_g), explain_vec(c, sizeof c, v), shader_name(shader),
        explain_color(kd, sizeof kd, shader->diffuse_color));
}

void explain_radiance(color L)
{
    explainer *e = explain_now;
    close_passing(e, false);
    explain_node *r = current_ray(e);
    if (!r)
        return;
    r->has_radiance = true;
    r->radiance = L;
    e->current = r->parent; /* back to the point that sent it */
    while (e->current >= 0 && e->nodes[e->current].type == NODE_RAY && e->nodes[e->current].kind == RAY_SHADOW)
        e->current = e->nodes[e->current].parent;
}

static int light_index(const explainer *e, vec3 position)
{
    for (int k = 0; e->desc && k < e->desc->n_lights; k++) {
        vec3 q = e->desc->lights[k].position;
        if (q.x == position.x && q.y == position.y && q.z == position.z)
            return k;
    }
    return -1;
}

void explain_light(const scene_light *light, vec3 x, vec3 n, vec3 v, color lambert, bool specular, color spec)
{
    explainer *e = explain_now;
    close_passing(e, false);
    vec3 to_light = vec3_sub(light->position, x);
    real r2 = vec3_length_squared(to_light);
    vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));
    char a[96], b[96], c[96];
    int k = add(e, NODE_LINE, "light %d at %s, I = %s: r^2 = %.9g, l = %s, n . l = %.9g", light_index(e, light->position),
                explain_vec(a, sizeof a, light->position), explain_color(b, sizeof b, light->intensity), (double)r2,
                explain_vec(c, sizeof c, l), (double)vec3_dot(n, l));
    if (k < 0)
        return;
    int back = e->current;
    e->current = k;
    add(e, NODE_LINE, "Lambert term k_d max(0, n . l) I / r^2 = %s", explain_color(a, sizeof a, lambert));
    color total = lambert;
    if (specular) {
        vec3 h = vec3_normalize(vec3_add(v, l));
        add(e, NODE_LINE, "h = (v + l) / |v + l| = %s, n . h = %.9g, specular term = %s", explain_vec(a, sizeof a, h),
            (double)vec3_dot(n, h), explain_color(b, sizeof b, spec));
        total = color_add(total, spec);
    }
    add(e, NODE_LINE, "this light's contribution = %s", explain_color(a, sizeof a, total));
    e->current = back;
}

void explain_ambient(color L_a)
{
    explainer *e = explain_now;
    close_passing(e, false);
    char a[96];
    add(e, NODE_LINE, "ambient term L_a = %s", explain_color(a, sizeof a, L_a));
}

void explain_spawn(const char *policy, vec3 x, vec3 origin, vec3 n_g)
{
    explainer *e = explain_now;
    vec3 offset = vec3_sub(origin, x);
    real size = vec3_length(offset);
    const char *along = size == 0 ? "" : vec3_dot(offset, n_g) == 0 ? "" : " along the geometric normal";
    if (size != 0 && real_abs(vec3_dot(offset, n_g)) < (real)0.999 * size)
        along = " along the ray";
    snprintf(e->spawn, sizeof e->spawn, "(--shadow-eps=%s: moved %.3g%s from x)", policy, (double)size, along);
}

void explain_shadow_ray(ray r, real t_max, vec3 target)
{
    explainer *e = explain_now;
    close_passing(e, false);
    char p[96], d[96];
    int k = add(e, NODE_RAY, "shadow ray to light %d: p = %s %s, d = light - p = %s, t in (0, %.9g)",
                light_index(e, target), explain_vec(p, sizeof p, r.p), e->spawn, explain_vec(d, sizeof d, r.d),
                (double)t_max);
    e->spawn[0] = '\0';
    if (k < 0)
        return;
    e->nodes[k].kind = RAY_SHADOW;
    e->nodes[k].r = r;
    e->nodes[k].t_end = t_max;
    e->current = k;
}

void explain_path_stop(bool depth_exhausted, int depth, real weight, real min_weight)
{
    explainer *e = explain_now;
    close_passing(e, false);
    if (depth_exhausted)
        add(e, NODE_LINE, "no deeper ray: depth %d is the deepest traced (--depth); it brings black", depth);
    else
        add(e, NODE_LINE, "no deeper ray: its path weight %.6g is below --min-weight %.6g; it brings black",
            (double)weight, (double)min_weight);
}

void explain_glass(real eta_i, real eta_t, real cos_i, bool transmits, real cos_t, real R)
{
    explainer *e = explain_now;
    close_passing(e, false);
    const char *way = eta_i < eta_t ? "entering" : "leaving";
    if (transmits)
        add(e, NODE_LINE,
            "glass, %s: eta_i = %.6g, eta_t = %.6g, cos theta_i = v . n = %.9g, cos theta_t = %.9g, Fresnel R = %.9g, "
            "1 - R = %.9g",
            way, (double)eta_i, (double)eta_t, (double)cos_i, (double)cos_t, (double)R, (double)(1 - R));
    else
        add(e, NODE_LINE,
            "glass, %s: eta_i = %.6g, eta_t = %.6g, cos theta_i = v . n = %.9g: past the critical angle "
            "(sin theta_c = eta_t / eta_i = %.6g, sin theta_i = %.6g): total internal reflection, R = %.6g",
            way, (double)eta_i, (double)eta_t, (double)cos_i, (double)(eta_t / eta_i),
            (double)real_sqrt(real_fmax(0, 1 - cos_i * cos_i)), (double)R);
}

void explain_interp(int source, real beta, real gamma, bool smooth, vec3 n_s, bool has_uv, real u, real v)
{
    explainer *e = explain_now;
    close_passing(e, false);
    char a[96];
    if (!e->desc || e->desc->surfaces[source].kind != SURFACE_MESH) {
        if (has_uv)
            add(e, NODE_LINE, "the sphere's texture coordinates (u, v) = (%.9g, %.9g)", (double)u, (double)v);
        return;
    }
    add(e, NODE_LINE, "at the mesh face: alpha = %.6g, beta = %.6g, gamma = %.6g; %s%s%s", (double)(1 - beta - gamma),
        (double)beta, (double)gamma, smooth ? "interpolated normal " : "no vertex normals (flat)",
        smooth ? explain_vec(a, sizeof a, n_s) : "", has_uv ? "" : "; no texture coordinates");
    if (has_uv)
        add(e, NODE_LINE, "texture coordinates (u, v) = (%.9g, %.9g)", (double)u, (double)v);
}

void explain_texel(real u, real v, const char *filter, color k_d)
{
    explainer *e = explain_now;
    char a[96];
    add(e, NODE_LINE, "texture at (u, v) = (%.6g, %.6g), %s: k_d = %s", (double)u, (double)v, filter,
        explain_color(a, sizeof a, k_d));
}

void explain_cell(int i, int j, int k, long surfaces)
{
    explainer *e = explain_now;
    close_passing(e, true);
    int c = add(e, NODE_CELL, "cell (%d, %d, %d): %ld surface%s", i, j, k, surfaces, surfaces == 1 ? "" : "s");
    if (c >= 0)
        e->current = c;
}
