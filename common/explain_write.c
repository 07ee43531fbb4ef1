/* explain_write.c - the tree of explain_tree.h as indented text and as JSON. */
#include <stdlib.h>
#include <string.h>

#include "explain_tree.h"
#include "output_file.h"

/* What a ray's last line says: the radiance it brought, or what became of a shadow ray. */
static void ray_outcome(const explain_node *n, char *buf, size_t size)
{
    char c[96];
    buf[0] = '\0';
    if (n->kind == RAY_SHADOW)
        snprintf(buf, size, n->blocked ? "blocked: the light is shadowed (nearest blocker at t = %.9g)"
                                       : "nothing blocks it: the light reaches the point",
                 (double)n->t_end);
    else if (n->has_radiance)
        snprintf(buf, size, "L = %s: what this ray brings back", explain_color(c, sizeof c, n->radiance));
}

/* A node's line; the line that counts the misses not listed says how many. */
static const char *tally_text(const explainer *e, int k, char *buf, size_t size)
{
    const explain_node *n = &e->nodes[k];
    if (n->type != NODE_LINE || n->parent < 0 || e->nodes[n->parent].tally != k)
        return n->text;
    snprintf(buf, size, "(%d more misses, not listed)", e->nodes[n->parent].hidden);
    return buf;
}

static void text_node(const explainer *e, int k, int indent, FILE *out)
{
    const explain_node *n = &e->nodes[k];
    char tally[80];
    fprintf(out, "%*s%s\n", 2 * indent, "", tally_text(e, k, tally, sizeof tally));
    for (int c = n->first; c >= 0; c = e->nodes[c].next)
        text_node(e, c, indent + 1, out);
    char outcome[200];
    if (n->type == NODE_RAY) {
        ray_outcome(n, outcome, sizeof outcome);
        if (outcome[0])
            fprintf(out, "%*s%s\n", 2 * indent + 2, "", outcome);
    }
}

void explain_write_text(const explainer *e, FILE *out)
{
    if (e->n > 0)
        text_node(e, 0, 0, out);
    if (e->full)
        fprintf(out,
                "(the explanation stops here: it holds at most %d rays, tests and terms, and what came after them "
                "is left out; a smaller --depth, a larger --min-weight or fewer --samples give a whole tree)\n",
                EXPLAIN_MAX_NODES);
    else if (e->failed)
        fprintf(out, "(out of memory: the explanation is incomplete)\n");
}

static void json_string(const char *s, FILE *out)
{
    fputc('"', out);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fputc('\\', out);
        fputc(*s, out);
    }
    fputc('"', out);
}

/* A real as JSON: a number, or null when it is not finite. */
static void json_real(real x, FILE *out)
{
    if (isfinite(x))
        fprintf(out, "%.17g", (double)x);
    else
        fputs("null", out);
}

static void json_vec(vec3 a, FILE *out)
{
    fputc('[', out);
    json_real(a.x, out);
    fputs(", ", out);
    json_real(a.y, out);
    fputs(", ", out);
    json_real(a.z, out);
    fputc(']', out);
}

static void json_node(const explainer *e, int k, int indent, FILE *out)
{
    static const char *const types[] = {"line", "ray", "test", "cell", "sample", "pixel"};
    static const char *const kinds[RAY_KINDS] = {"eye", "shadow", "reflected", "refracted"};
    const explain_node *n = &e->nodes[k];
    char tally[80];
    fprintf(out, "%*s{\"type\": \"%s\", \"text\": ", indent, "", types[n->type]);
    json_string(tally_text(e, k, tally, sizeof tally), out);
    if (n->type == NODE_RAY) {
        fprintf(out, ", \"kind\": \"%s\", \"depth\": %d, \"p\": ", kinds[n->kind], n->depth);
        json_vec(n->r.p, out);
        fputs(", \"d\": ", out);
        json_vec(n->r.d, out);
        fputs(", \"t_end\": ", out);
        json_real(n->t_end, out);
        if (n->kind == RAY_SHADOW)
            fprintf(out, ", \"blocked\": %s", n->blocked ? "true" : "false");
        if (n->has_radiance) {
            fputs(", \"L\": ", out);
            json_vec(vec3_make(n->radiance.r, n->radiance.g, n->radiance.b), out);
        }
    }
    if (n->type == NODE_TEST) {
        fprintf(out, ", \"surface\": %d, \"hit\": %s, \"t\": ", n->surface, n->hit ? "true" : "false");
        json_real(n->hit ? n->t : REAL_INFINITY, out);
    }
    fputs(", \"children\": [", out);
    for (int c = n->first; c >= 0; c = e->nodes[c].next) {
        fputs(c == n->first ? "\n" : ",\n", out);
        json_node(e, c, indent + 2, out);
    }
    if (n->first >= 0)
        fprintf(out, "\n%*s", indent, "");
    fputs("]}", out);
}

int explain_write_json(const explainer *e, const char *path, const char *pixel_json, char *err, size_t err_size)
{
    output_file f;
    if (output_open(&f, path, err, err_size) != 0)
        return -1;
    fprintf(f.file, "{\n  \"pixel\": %s,\n  \"complete\": %s,\n  \"tree\":\n", pixel_json, e->failed ? "false" : "true");
    if (e->n > 0)
        json_node(e, 0, 2, f.file);
    else
        fputs("  null", f.file);
    fputs("\n}\n", f.file);
    return output_close(&f, 0, "the JSON", err, err_size);
}
