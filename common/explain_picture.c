/* explain_picture.c - the rays of an explained pixel, drawn for a slide.
 *
 * Three panels side by side: the rendered image with the pixel marked, the
 * scene seen from above (x to the right, -z up) and from the side (-z to the
 * right, y up), both orthographic and at the same scale, the pixel's rays
 * drawn over the scene's outlines as labelled segments: eye (black), shadow
 * (blue; a blocked one ends in a red cross), reflected (green), refracted
 * (magenta).  A ray that hits nothing runs to the panel's edge.
 */
#include <stdlib.h>
#include <string.h>

#include "../tools/font5x7.h"
#include "display.h"
#include "explain_tree.h"
#include "png_write.h"

static const double PI = 3.14159265358979323846;

enum { SIDE = 360, LABEL = 24, GAP = 12, LEGEND = 22 };

typedef struct {
    uint8_t *px;
    int width, height;
    int x0, y0, x1, y1; /* only [x0, x1) x [y0, y1) is drawn into */
} canvas;

typedef struct {
    uint8_t r, g, b;
} rgb;

static const rgb black = {0, 0, 0}, grey = {170, 170, 170}, red = {220, 0, 0}, light_colour = {230, 160, 0};
static const rgb kind_colour[RAY_KINDS] = {{0, 0, 0}, {30, 90, 230}, {0, 150, 60}, {200, 0, 200}};
static const char *const kind_label[RAY_KINDS] = {"eye", "shadow", "reflected", "refracted"};

static void dot(canvas *c, int x, int y, rgb colour)
{
    if (x < c->x0 || y < c->y0 || x >= c->x1 || y >= c->y1)
        return;
    uint8_t *p = c->px + 3 * ((size_t)y * (size_t)c->width + (size_t)x);
    p[0] = colour.r;
    p[1] = colour.g;
    p[2] = colour.b;
}

/* A straight line, `thick` pixels wide, from (x0, y0) to (x1, y1) in canvas pixels. */
static void line(canvas *c, double x0, double y0, double x1, double y1, int thick, rgb colour)
{
    double steps = fmax(fabs(x1 - x0), fabs(y1 - y0));
    if (!(steps < 1e5)) /* far off the canvas: clipped by steps, not drawn to infinity */
        steps = 1e5;
    for (int s = 0; s <= (int)steps; s++) {
        double f = steps > 0 ? s / steps : 0;
        int x = (int)lround(x0 + f * (x1 - x0)), y = (int)lround(y0 + f * (y1 - y0));
        for (int a = 0; a < thick; a++)
            for (int b = 0; b < thick; b++)
                dot(c, x + a - thick / 2, y + b - thick / 2, colour);
    }
}

/* Text in the 5 x 7 font of tools/font5x7.h, `scale` canvas pixels a font pixel, top-left at (x, y). */
static void text(canvas *c, int x, int y, const char *s, int scale, rgb colour)
{
    for (; *s; s++, x += 6 * scale)
        for (int row = 0; row < 9; row++)
            for (int col = 0; col < 5; col++)
                if (font5x7_ink(*s, row, col))
                    for (int a = 0; a < scale * scale; a++)
                        dot(c, x + col * scale + a % scale, y + row * scale + a / scale, colour);
}

/* A view: world point -> panel pixel, for the panel whose top-left corner is (left, top). */
typedef struct {
    vec3 right, up; /* world directions of the panel's x and (upwards) y */
    double cx, cy, scale;
    int left, top;
} view;

static void project(const view *v, vec3 p, double *x, double *y)
{
    *x = v->left + SIDE / 2.0 + ((double)vec3_dot(p, v->right) - v->cx) * v->scale;
    *y = v->top + SIDE / 2.0 - ((double)vec3_dot(p, v->up) - v->cy) * v->scale;
}

static void segment(canvas *c, const view *v, vec3 a, vec3 b, int thick, rgb colour)
{
    double x0, y0, x1, y1;
    project(v, a, &x0, &y0);
    project(v, b, &x1, &y1);
    line(c, x0, y0, x1, y1, thick, colour);
}

/* The far end of ray node n in the picture: its end, or a long way along it. */
static vec3 ray_end(const explain_node *n, real reach)
{
    real t = n->t_end;
    if (!isfinite(t))
        t = reach / vec3_length(n->r.d);
    return ray_at(n->r, t);
}

/* Fits the view to the rays' points: origins and finite ends. */
static void fit(const explainer *e, view *v)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < e->n; k++) {
        const explain_node *n = &e->nodes[k];
        if (n->type != NODE_RAY)
            continue;
        vec3 points[2] = {n->r.p, isfinite(n->t_end) ? ray_at(n->r, n->t_end) : n->r.p};
        for (int p = 0; p < 2; p++) {
            double xy[2] = {(double)vec3_dot(points[p], v->right), (double)vec3_dot(points[p], v->up)};
            for (int a = 0; a < 2; a++) {
                lo[a] = fmin(lo[a], xy[a]);
                hi[a] = fmax(hi[a], xy[a]);
            }
        }
    }
    if (!(lo[0] <= hi[0])) { /* no ray at all */
        lo[0] = lo[1] = -1;
        hi[0] = hi[1] = 1;
    }
    double extent = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), 1e-6);
    v->cx = (lo[0] + hi[0]) / 2;
    v->cy = (lo[1] + hi[1]) / 2;
    v->scale = SIDE / (1.5 * extent);
}

static void outline_triangle(canvas *c, const view *v, vec3 a, vec3 b, vec3 d)
{
    segment(c, v, a, b, 1, grey);
    segment(c, v, b, d, 1, grey);
    segment(c, v, d, a, 1, grey);
}

/* The scene's surfaces and lights, in grey and orange. */
static void draw_scene(canvas *c, const view *v, const scene *desc)
{
    for (int k = 0; k < desc->n_surfaces; k++) {
        const scene_surface *s = &desc->surfaces[k];
        if (s->kind == SURFACE_SPHERE) {
            double x, y;
            project(v, s->center, &x, &y);
            double R = (double)s->radius * v->scale;
            int steps = (int)fmin(fmax(16, 8 * R), 4000);
            for (int a = 0; a < steps; a++) {
                double t0 = 2 * PI * a / steps, t1 = 2 * PI * (a + 1) / steps;
                line(c, x + R * cos(t0), y + R * sin(t0), x + R * cos(t1), y + R * sin(t1), 1, grey);
            }
        } else if (s->kind == SURFACE_TRIANGLE) {
            outline_triangle(c, v, s->v0, s->v1, s->v2);
        } else if (s->kind == SURFACE_BOX) {
            vec3 lo = s->min_pt, hi = s->max_pt;
            for (int corner = 0; corner < 8; corner++)
                for (int axis = 0; axis < 3; axis++)
                    if (!(corner >> axis & 1)) {
                        int other = corner | 1 << axis;
                        vec3 a = {corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
                        vec3 b = {other & 1 ? hi.x : lo.x, other & 2 ? hi.y : lo.y, other & 4 ? hi.z : lo.z};
                        segment(c, v, a, b, 1, grey);
                    }
        } else if (s->kind == SURFACE_MESH) {
            const mesh *m = &desc->meshes[s->mesh];
            for (int f = 0; f < m->n_faces; f++)
                outline_triangle(c, v, m->positions[m->faces[f].v[0]], m->positions[m->faces[f].v[1]],
                                 m->positions[m->faces[f].v[2]]);
        }
    }
    for (int k = 0; k < desc->n_lights; k++) {
        double x, y;
        project(v, desc->lights[k].position, &x, &y);
        for (int a = -3; a <= 3; a++)
            line(c, x - 3, y + a, x + 3, y + a, 1, light_colour);
        char name[24];
        snprintf(name, sizeof name, "light %d", k);
        text(c, (int)x + 6, (int)y - 3, name, 1, light_colour);
    }
}

/* The rays, each labelled at its middle; a blocked shadow ray's end crossed out. */
static void draw_rays(canvas *c, const view *v, const explainer *e)
{
    const real reach = (real)(4 * SIDE / v->scale);
    for (int k = 0; k < e->n; k++) {
        const explain_node *n = &e->nodes[k];
        if (n->type != NODE_RAY)
            continue;
        vec3 end = ray_end(n, reach);
        segment(c, v, n->r.p, end, 2, kind_colour[n->kind]);
        double x0, y0, x1, y1;
        project(v, n->r.p, &x0, &y0);
        project(v, end, &x1, &y1);
        if (!isfinite(n->t_end)) { /* the label where the ray leaves the panel */
            double f = fmin(1, (SIDE / 3.0) / fmax(hypot(x1 - x0, y1 - y0), 1));
            x1 = x0 + f * (x1 - x0);
            y1 = y0 + f * (y1 - y0);
        }
        if (n->kind == RAY_SHADOW && n->blocked) {
            line(c, x1 - 6, y1 - 6, x1 + 6, y1 + 6, 3, red);
            line(c, x1 - 6, y1 + 6, x1 + 6, y1 - 6, 3, red);
            text(c, (int)x1 + 8, (int)y1 + 4, "blocked", 1, red);
        } else if (isfinite(n->t_end)) {
            line(c, x1 - 2, y1, x1 + 2, y1, 5, kind_colour[n->kind]);
        }
        text(c, (int)((x0 + x1) / 2) + 5, (int)((y0 + y1) / 2) - 10, kind_label[n->kind], 1, kind_colour[n->kind]);
    }
    double x, y;
    for (int k = 0; k < e->n; k++)
        if (e->nodes[k].type == NODE_RAY && e->nodes[k].kind == RAY_EYE) {
            project(v, e->nodes[k].r.p, &x, &y);
            line(c, x - 3, y, x + 3, y, 7, black);
        }
}

/* The rendered image, scaled to SIDE high, pixel (x, y) framed in red. */
static int draw_image(canvas *c, const image *img, real exposure, int x, int y)
{
    double s = (double)SIDE / img->height;
    int w = (int)lround(img->width * s);
    for (int py = 0; py < SIDE; py++)
        for (int px = 0; px < w; px++) {
            int i = (int)fmin(px / s, img->width - 1), row = (int)fmin(py / s, img->height - 1);
            color L = *image_at(img, i, img->height - 1 - row);
            dot(c, px, LABEL + py, (rgb){display_encode(L.r, exposure), display_encode(L.g, exposure),
                                         display_encode(L.b, exposure)});
        }
    double x0 = x * s, y0 = LABEL + y * s, side = fmax(s, 1);
    const double m = 4;
    line(c, x0 - m, y0 - m, x0 + side + m, y0 - m, 2, red);
    line(c, x0 - m, y0 + side + m, x0 + side + m, y0 + side + m, 2, red);
    line(c, x0 - m, y0 - m, x0 - m, y0 + side + m, 2, red);
    line(c, x0 + side + m, y0 - m, x0 + side + m, y0 + side + m, 2, red);
    return w;
}

int explain_write_picture(const explainer *e, const image *img, real exposure, int x, int y, const char *path,
                          char *err, size_t err_size)
{
    int image_width = (int)lround(img->width * ((double)SIDE / img->height));
    canvas c = {.width = image_width + 2 * (GAP + SIDE), .height = LABEL + SIDE + LEGEND};
    c.x1 = c.width;
    c.y1 = c.height;
    c.px = malloc((size_t)c.width * (size_t)c.height * 3);
    if (!c.px) {
        snprintf(err, err_size, "%s: out of memory", path);
        return -1;
    }
    memset(c.px, 255, (size_t)c.width * (size_t)c.height * 3);
    draw_image(&c, img, exposure, x, y);
    char label[64];
    snprintf(label, sizeof label, "pixel (%d, %d)", x, y);
    text(&c, 4, 6, label, 2, black);
    view views[2] = {
        {.right = {1, 0, 0}, .up = {0, 0, -1}, .left = image_width + GAP, .top = LABEL},
        {.right = {0, 0, -1}, .up = {0, 1, 0}, .left = image_width + 2 * GAP + SIDE, .top = LABEL},
    };
    static const char *const titles[2] = {"from above: x right, -z up", "from the side: -z right, y up"};
    for (int k = 0; k < 2; k++) {
        fit(e, &views[k]);
        canvas panel = c; /* clipped to the view's square */
        panel.x0 = views[k].left;
        panel.x1 = views[k].left + SIDE;
        panel.y0 = LABEL;
        panel.y1 = LABEL + SIDE;
        if (e->desc)
            draw_scene(&panel, &views[k], e->desc);
        draw_rays(&panel, &views[k], e);
    }
    for (int k = 0; k < 2; k++) {
        text(&c, views[k].left + 4, 6, titles[k], 2, black);
        line(&c, views[k].left, LABEL, views[k].left, LABEL + SIDE - 1, 1, black);
    }
    int lx = image_width + GAP;
    for (int k = 0; k < RAY_KINDS; k++, lx += 110) {
        line(&c, lx, LABEL + SIDE + 11, lx + 20, LABEL + SIDE + 11, 2, kind_colour[k]);
        text(&c, lx + 26, LABEL + SIDE + 7, kind_label[k], 1, kind_colour[k]);
    }
    int status = png_write_rgb(c.px, c.width, c.height, path, err, err_size);
    free(c.px);
    return status;
}
