/* explain_tree.h - what the recorder of explain.h keeps: a tree of nodes.
 *
 * A node is a line of the explanation (a sample, a test, a term) or a ray;
 * a ray's children are what happened along it.  explain.c builds the tree,
 * explain_write.c prints it as text and JSON, explain_picture.c draws its
 * rays.
 */
#ifndef RT_EXPLAIN_TREE_H
#define RT_EXPLAIN_TREE_H

#include "explain.h"

typedef enum { NODE_LINE, NODE_RAY, NODE_TEST, NODE_CELL, NODE_SAMPLE, NODE_ROOT } node_type;

/* The most nodes a tree holds (about 50 MB, and as many lines): a pixel of
 * glass in glass at --min-weight=0 doubles its rays at every depth, and 65536
 * samples make as many subtrees.  Beyond it the reports are dropped and the
 * explanation says where it stops. */
#define EXPLAIN_MAX_NODES 100000

/* Misses listed under one ray (or cell); the rest are counted. */
#define EXPLAIN_MISSES_SHOWN 6

typedef struct {
    node_type type;
    int parent, first, last, next; /* the tree's links; -1 for none */
    char text[400];                /* the line; a ray's is its first line, completed when it ends */
    /* NODE_RAY */
    ray_kind kind;     /* RAY_EYE, RAY_SHADOW, RAY_REFLECTED, RAY_REFRACTED */
    int depth;
    ray r;
    real t_end;        /* where it ends in the picture: the closest hit, the blocker, t_max; INFINITY: nowhere */
    bool blocked;      /* a shadow ray that hit something */
    bool has_radiance; /* a traced ray: the radiance it brought */
    color radiance;
    /* NODE_RAY, NODE_CELL: its tests so far, how many missed, how many of those are not listed, and the
     * line that counts them */
    int tests, misses, hidden, tally;
    /* NODE_TEST */
    int surface; /* index in the list, -1 when unknown */
    int order;   /* 1 for the ray's (or cell's) first test, ... */
    bool hit;
    real t;
} explain_node;

struct explainer {
    explain_node *nodes;
    int n, capacity;
    int current;      /* the node reports go to */
    int open[260];    /* the traced ray of each depth (PATH_MAX_DEPTH of chapter 08, and some) */
    uint64_t seen[RAY_KINDS]; /* the ray counters at the last trace(): the next one's kind is the one that grew */
    char spawn[200];  /* how the next secondary ray left its surface (spawn_ray), for its line */
    int surface, source, face; /* the surface the next test is of (explain_surface); -1: unknown */
    const scene *desc;
    bool failed;      /* out of memory, or full (EXPLAIN_MAX_NODES): the tree is incomplete */
    bool full;        /* it stopped at EXPLAIN_MAX_NODES */
};

/* An empty recorder for the scene desc, whose root line is `root`. */
void explain_init(explainer *e, const scene *desc, const char *root);

/* The children of node k, in order: for (int c = t->nodes[k].first; c >= 0; c = t->nodes[c].next). */

/* "(x, y, z)" with 6 significant digits, into buf. */
const char *explain_vec(char *buf, size_t size, vec3 a);
const char *explain_color(char *buf, size_t size, color c);

/* The text and the JSON of the tree (explain_write.c). */
void explain_write_text(const explainer *e, FILE *out);
int explain_write_json(const explainer *e, const char *path, const char *pixel_json, char *err, size_t err_size);

/* The picture (explain_picture.c): the image with the pixel marked, and the
 * rays seen from above and from the side. */
int explain_write_picture(const explainer *e, const image *img, real exposure, int x, int y, const char *path,
                          char *err, size_t err_size);

#endif
