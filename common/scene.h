/* scene.h - the plain description of a scene file (docs/scenes.md).
 *
 * scene_load() reads and validates every element docs/scenes.md defines, even
 * those no chapter models yet, into these plain structs.  Each chapter reads
 * the parts its stage needs and names the parts it ignores (scene_features).
 * Every item keeps the line it was defined on, for error messages.
 */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include <stdbool.h>
#include <stddef.h>

#include "color.h"
#include "mesh.h"
#include "texture_image.h"
#include "vec3.h"

typedef enum { CAMERA_PERSPECTIVE, CAMERA_ORTHOGRAPHIC } camera_kind;

typedef struct {
    camera_kind kind;
    vec3 view_point, view_dir, view_up; /* defaults (0 0 0), (0 0 -1), (0 1 0) */
    real proj_distance;                 /* perspective only; default 1 */
    real view_width, view_height;       /* default 1, 1 */
    int line;
} scene_camera;

typedef enum { TEXTURE_REPEAT, TEXTURE_CLAMP } texture_kind;

typedef struct {
    char *name;
    texture_kind kind;
    char *image_path;    /* resolved against the scene file's folder */
    texture_image image; /* its texels, decoded when the scene was read: look them up here */
    int line;
} scene_texture;

typedef enum { SHADER_LAMBERTIAN, SHADER_PHONG, SHADER_RGB_NORMALS, SHADER_GLASS } shader_kind;

typedef struct {
    char *name;               /* NULL for a shader defined inside a surface */
    shader_kind kind;
    color diffuse_color;      /* the course's k_d = R / pi; default (1 1 1) */
    color specular_color;     /* k_s; default (1 1 1) */
    real exponent;            /* Phong exponent p; default 1 */
    color mirror_coefficient; /* k_m; default 0 (no mirror) */
    real refractive_index;    /* eta of a Glass shader; default 1.5 */
    int texture;              /* index into scene.textures, or -1 */
    int line;
} scene_shader;

typedef enum { SURFACE_SPHERE, SURFACE_BOX, SURFACE_MESH, SURFACE_TRIANGLE } surface_kind;

typedef struct {
    surface_kind kind;
    int shader;          /* index into scene.shaders; -1: white Lambertian */
    vec3 center;         /* Sphere; default (0 0 0) */
    real radius;         /* Sphere; default 1, always > 0 */
    vec3 min_pt, max_pt; /* Box; min_pt <= max_pt component-wise (the reader sorts them) */
    vec3 v0, v1, v2;     /* Triangle */
    int mesh;            /* Mesh: index into scene.meshes */
    int line;
} scene_surface;

typedef struct {
    vec3 position;   /* default (0 0 0) */
    color intensity; /* I; default (1 1 1) */
    int line;
} scene_light;

typedef struct {
    char *path; /* the scene file as given */
    int width, height; /* <image>; 0 when the file has none */
    bool has_camera;
    scene_camera camera; /* the defaults when has_camera is false */
    real exposure;       /* default 1 */
    color back_color;    /* default black */
    color ambient;       /* default black */
    int samples;         /* <samples>; 0 when the file has none */
    scene_shader *shaders;
    int n_shaders;
    scene_texture *textures;
    int n_textures;
    scene_surface *surfaces;
    int n_surfaces;
    scene_light *lights;
    int n_lights;
    mesh *meshes;
    int n_meshes;
} scene;

#define SCENE_MAX_IMAGE_SIDE 16384
#define SCENE_MAX_FILE_BYTES (64LL << 20) /* one scene file; also keeps line numbers far from INT_MAX */

/* The defaults of docs/scenes.md: no surfaces, the default camera, exposure 1. */
void scene_init(scene *s);

/* What a message calls the scene: its path, or "built-in scene". */
const char *scene_name(const scene *s);

/* Reads `path`.  Returns 0, or -1 with "path:line: problem" in err (and s
 * left empty: nothing to free).  Mesh and texture paths are resolved against
 * the folder of `path`; meshes are loaded and texture images decoded, each
 * once.  The scene, a mesh or a texture that is not a regular file (a
 * directory, a FIFO, /dev/zero) or is larger than its limit is refused. */
int scene_load(const char *path, scene *s, char *err, size_t err_size);

void scene_free(scene *s);

/* The features of a scene file, for the "ignored" line of each chapter. */
typedef enum {
    FEATURE_SPHERES = 1 << 0,
    FEATURE_TRIANGLES = 1 << 1, /* Triangle surfaces */
    FEATURE_BOXES = 1 << 2,
    FEATURE_MESHES = 1 << 3,
    FEATURE_LIGHTS = 1 << 4,
    FEATURE_PHONG = 1 << 5,
    FEATURE_AMBIENT = 1 << 6,
    FEATURE_MIRRORS = 1 << 7,
    FEATURE_GLASS = 1 << 8,
    FEATURE_TEXTURES = 1 << 9,
    FEATURE_VERTEX_NORMALS = 1 << 10, /* meshes with per-vertex normals */
    FEATURE_RGB_NORMALS = 1 << 11,
    FEATURE_SHADERS = 1 << 12, /* any shader colour at all */
    FEATURE_SHADOWS = 1 << 13, /* every scene with lights casts shadows */
    FEATURE_MANY_LIGHTS = 1 << 14, /* more than one light (05 and 06 shade with the first) */
} scene_feature;

unsigned scene_features(const scene *s);

/* "ignores: lights (chapter 05), Phong (chapter 07)" for the features in
 * `used` that the chapter does not model (`modelled`); writes "" when none. */
void scene_ignored_features(unsigned used, unsigned modelled, char *out, size_t out_size);

#endif
