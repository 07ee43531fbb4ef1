/* The scene reader (common/scene.h): every element, every error path, the
 * OBJ meshes, and the whole Cornell corpus. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb_image_write.h>

#include "scene.h"
#include "scene_cost.h"
#include "suite.h"

static char folder[64];

static int make_folder(void **state)
{
    (void)state;
    strcpy(folder, "/tmp/rt-scene-XXXXXX");
    return mkdtemp(folder) ? 0 : -1;
}

static int remove_folder(void **state)
{
    (void)state;
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", folder);
    return system(command) == 0 ? 0 : -1;
}

/* Writes `text` to folder/name and returns the path (static buffer). */
static const char *write_file(const char *name, const char *text)
{
    static char path[256];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    return path;
}

/* Loads a scene from text; returns the status, the message in err. */
static int load_text(const char *text, scene *s, char *err, size_t err_size)
{
    return scene_load(write_file("scene.xml", text), s, err, err_size);
}

/* The scene must be rejected with "scene.xml:LINE: ..." containing `words`. */
static void expect_error(const char *text, int line, const char *words)
{
    scene s;
    char err[1024] = "";
    int status = load_text(text, &s, err, sizeof err);
    char where[64];
    snprintf(where, sizeof where, "scene.xml:%d: ", line);
    if (status != -1 || !strstr(err, where) || !strstr(err, words))
        fail_msg("expected an error at line %d mentioning '%s', got status %d and '%s'", line, words, status, err);
    assert_int_equal(0, s.n_surfaces); /* nothing left to free */
}

static const char full_scene[] =
    "<?xml version=\"1.0\"?>\n"
    "<scene>\n"                                                      /* 2 */
    "  <image>320 200</image>\n"                                     /* 3 */
    "  <exposure>2.5</exposure>\n"                                   /* 4 */
    "  <backColor>.1 .2 .3</backColor>\n"                            /* 5 */
    "  <ambient>.01 .02 .03</ambient>\n"                             /* 6 */
    "  <samples>4</samples>\n"                                       /* 7 */
    "  <camera type=\"OrthographicCamera\">\n"                       /* 8 */
    "    <viewPoint>10 4.2 6</viewPoint><viewDir>-5 -2.1 -3</viewDir>\n"
    "    <viewUp>0 1 0</viewUp><viewWidth>8</viewWidth><viewHeight>5</viewHeight>\n"
    "  </camera>\n"
    "  <texture name=\"tex\" type=\"ClampTexture\"><image>t.png</image></texture>\n" /* 12 */
    "  <shader name=\"red\" type=\"Lambertian\"><diffuseColor>1 0 0</diffuseColor>\n"
    "    <mirrorCoefficient>.5 .5 .5</mirrorCoefficient></shader>\n"
    "  <shader name=\"shiny\" type=\"Phong\"><diffuseColor>.5 .5 .5</diffuseColor>\n"
    "    <specularColor>.8 .8 .8</specularColor><exponent>50</exponent><texture ref=\"tex\"/></shader>\n"
    "  <shader name=\"glass\" type=\"Glass\"><refractiveIndex>1.33</refractiveIndex></shader>\n"
    "  <shader name=\"n\" type=\"RGBNormals\"/>\n"
    "  <surface type=\"Sphere\"><shader ref=\"red\"/><center>1 2 3</center><radius>.5</radius></surface>\n"
    "  <surface type=\"Box\"><shader ref=\"n\"/><minpt>1 -1 1</minpt><MAXPT>-1 1 -1</MAXPT></surface>\n"
    "  <surface type=\"Mesh\"><data>m.obj</data></surface>\n"
    "  <surface type=\"Triangle\"><shader type=\"Lambertian\"><diffuseColor>0 1 0</diffuseColor></shader>\n"
    "    <v0>0 0 0</v0><v1>1 0 0</v1><v2>0 1 0</v2></surface>\n"
    "  <surface type=\"Sphere\"><shader ref=\"glass\"/></surface>\n"
    "  <light><position>4 5 -3</position><intensity>10 10 10</intensity></light>\n"
    "  <light/>\n"
    "</scene>\n";

/* A 1x1 PNG, so that the texture check has a real image to read. */
static const unsigned char tiny_png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
    0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00, 0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00,
    0x0c, 0x49, 0x44, 0x41, 0x54, 0x08, 0xd7, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x00, 0x03, 0x01, 0x01, 0x00, 0x18,
    0xdd, 0x8d, 0xb0, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};

static void write_assets(void)
{
    char path[256];
    snprintf(path, sizeof path, "%s/t.png", folder);
    FILE *f = fopen(path, "wb");
    fwrite(tiny_png, 1, sizeof tiny_png, f);
    fclose(f);
    write_file("m.obj", "# a quad with texture coordinates and normals\n"
                        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                        "o quad\ns off\nf 1/1/1 2/2/1 3/3/1 4/4/1\n");
}

static void test_full_scene_values(void **state)
{
    (void)state;
    write_assets();
    scene s;
    char err[1024] = "";
    if (load_text(full_scene, &s, err, sizeof err) != 0)
        fail_msg("%s", err);
    assert_int_equal(320, s.width);
    assert_int_equal(200, s.height);
    assert_close(2.5, s.exposure, 0);
    assert_close(0.2, s.back_color.g, REAL_EPSILON);
    assert_close(0.03, s.ambient.b, REAL_EPSILON);
    assert_int_equal(4, s.samples);
    assert_true(s.has_camera);
    assert_int_equal(CAMERA_ORTHOGRAPHIC, s.camera.kind);
    assert_close(-2.1, s.camera.view_dir.y, 4 * REAL_EPSILON);
    assert_close(8, s.camera.view_width, 0);
    assert_int_equal(8, s.camera.line);
    assert_int_equal(1, s.n_textures);
    assert_int_equal(TEXTURE_CLAMP, s.textures[0].kind);
    assert_non_null(strstr(s.textures[0].image_path, folder)); /* resolved against the scene's folder */
    assert_int_equal(5, s.n_shaders);                            /* 4 named + 1 inline */
    assert_int_equal(SHADER_LAMBERTIAN, s.shaders[0].kind);
    assert_close(0.5, s.shaders[0].mirror_coefficient.r, 0);
    assert_int_equal(SHADER_PHONG, s.shaders[1].kind);
    assert_close(50, s.shaders[1].exponent, 0);
    assert_int_equal(0, s.shaders[1].texture);
    assert_int_equal(-1, s.shaders[0].texture);
    assert_close(1.33, s.shaders[2].refractive_index, 2 * REAL_EPSILON);
    assert_int_equal(SHADER_RGB_NORMALS, s.shaders[3].kind);
    assert_int_equal(5, s.n_surfaces);
    assert_int_equal(SURFACE_SPHERE, s.surfaces[0].kind);
    assert_int_equal(0, s.surfaces[0].shader);
    assert_vec3_close(vec3_make(1, 2, 3), s.surfaces[0].center, 0);
    assert_close(0.5, s.surfaces[0].radius, 0);
    /* Box corners given the wrong way round are sorted */
    assert_vec3_close(vec3_make(-1, -1, -1), s.surfaces[1].min_pt, 0);
    assert_vec3_close(vec3_make(1, 1, 1), s.surfaces[1].max_pt, 0);
    assert_int_equal(SURFACE_MESH, s.surfaces[2].kind);
    assert_int_equal(-1, s.surfaces[2].shader); /* no shader: white Lambertian */
    const mesh *m = &s.meshes[s.surfaces[2].mesh];
    assert_int_equal(4, m->n_positions);
    assert_int_equal(2, m->n_faces); /* the quad as a fan of two triangles */
    assert_int_equal(0, m->faces[1].v[0]); /* fan: (1, 3, 4) */
    assert_int_equal(2, m->faces[1].v[1]);
    assert_int_equal(3, m->faces[1].v[2]);
    assert_int_equal(3, m->faces[1].vt[2]);
    assert_int_equal(0, m->faces[1].vn[2]);
    assert_int_equal(SURFACE_TRIANGLE, s.surfaces[3].kind);
    assert_int_equal(4, s.surfaces[3].shader); /* the inline shader */
    assert_close(1, s.shaders[4].diffuse_color.g, 0);
    assert_vec3_close(vec3_make(1, 0, 0), s.surfaces[3].v1, 0);
    /* defaults: a Sphere at the origin of radius 1 */
    assert_vec3_close(vec3_make(0, 0, 0), s.surfaces[4].center, 0);
    assert_close(1, s.surfaces[4].radius, 0);
    assert_int_equal(2, s.n_lights);
    assert_close(10, s.lights[0].intensity.g, 0);
    assert_close(1, s.lights[1].intensity.r, 0); /* default intensity */
    unsigned f = scene_features(&s);
    /* "shiny" (Phong, textured) is used by no surface: its features do not count */
    unsigned all = FEATURE_SPHERES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_TRIANGLES | FEATURE_LIGHTS |
                   FEATURE_SHADOWS | FEATURE_AMBIENT | FEATURE_MIRRORS | FEATURE_GLASS | FEATURE_VERTEX_NORMALS |
                   FEATURE_RGB_NORMALS | FEATURE_SHADERS | FEATURE_MANY_LIGHTS;
    assert_int_equal(all, f);
    char ignored[512];
    scene_ignored_features(f, all & ~(FEATURE_GLASS | FEATURE_MIRRORS), ignored, sizeof ignored);
    assert_string_equal("ignores: mirrors (chapter 08), glass (chapter 09)", ignored);
    scene_ignored_features(f, all, ignored, sizeof ignored);
    assert_string_equal("", ignored);
    scene_free(&s);
}

static void test_defaults_of_an_empty_scene(void **state)
{
    (void)state;
    scene s;
    char err[512];
    assert_int_equal(0, load_text("<scene/>", &s, err, sizeof err));
    assert_false(s.has_camera);
    assert_int_equal(0, s.width);
    assert_close(1, s.exposure, 0);
    assert_vec3_close(vec3_make(0, 0, -1), s.camera.view_dir, 0);
    assert_vec3_close(vec3_make(0, 1, 0), s.camera.view_up, 0);
    assert_close(1, s.camera.proj_distance, 0);
    assert_int_equal(0, s.n_surfaces);
    assert_int_equal(0, scene_features(&s));
    scene_free(&s);
}

static void test_structure_errors(void **state)
{
    (void)state;
    expect_error("<scene>\n<sphere/>\n</scene>", 2, "unknown element <sphere>");
    expect_error("<scene>\n<surface type=\"Sphere\">\n<centre>0 0 0</centre></surface></scene>", 3,
                 "unknown element <centre>");
    expect_error("<world/>", 1, "root element must be <scene>");
    expect_error("<scene>\n<image>10 10</image>\n<image>5 5</image></scene>", 3, "appears twice");
    expect_error("<scene>\n<camera type=\"PerspectiveCamera\"/>\n<camera type=\"PerspectiveCamera\"/></scene>", 3,
                 "one <camera>");
    expect_error("<scene>\n<camera type=\"Pinhole\"/></scene>", 2, "unknown camera type 'Pinhole'");
    expect_error("<scene>\n<camera/></scene>", 2, "needs a type");
    expect_error("<scene>\n<surface type=\"Torus\"/></scene>", 2, "unknown surface type");
    expect_error("<scene>\n<shader type=\"Metal\"/></scene>", 2, "unknown shader type");
    expect_error("<scene>\n<camera type=\"OrthographicCamera\">\n<projDistance>2</projDistance></camera></scene>", 3,
                 "no meaning");
    expect_error("<scene>\n<surface type=\"Box\">\n<radius>2</radius></surface></scene>", 3, "no meaning");
    expect_error("<scene>\n<shader type=\"Lambertian\">\n<exponent>2</exponent></shader></scene>", 3, "no meaning");
    expect_error("<scene>\n<surface tipe=\"Sphere\"/></scene>", 2, "unknown attribute 'tipe'");
    expect_error("<scene>\n<exposure>1</exposure>text</scene>", 2, "unexpected text");
    expect_error("<scene>\n<image>10 10</image>\n</scen>", 3, "XML error");
    expect_error("<scene>\n<surface type=\"Box\"><minPt>0 0 0</minPt>\n</surface></scene>", 2, "needs <maxPt>");
    expect_error("<scene>\n<surface type=\"Mesh\"/></scene>", 2, "needs <data>");
    expect_error("<scene>\n<surface type=\"Triangle\"><v0>0 0 0</v0><v1>1 0 0</v1></surface></scene>", 2,
                 "needs <v2>");
    expect_error("<scene>\n<texture type=\"RepeatTexture\"/></scene>", 2, "needs <image>");
}

static void test_number_errors(void **state)
{
    (void)state;
    expect_error("<scene>\n<backColor>1 2</backColor></scene>", 2, "needs 3 numbers but has 2");
    expect_error("<scene>\n<backColor>1 2 x</backColor></scene>", 2, "malformed number 'x'");
    expect_error("<scene>\n<backColor>1 2 3 4</backColor></scene>", 2, "has more");
    expect_error("<scene>\n<exposure></exposure></scene>", 2, "needs 1 number but has 0");
    expect_error("<scene>\n<exposure>1e999</exposure></scene>", 2, "out of range");
    expect_error("<scene>\n<exposure>nan</exposure></scene>", 2, "out of range");
    expect_error("<scene>\n<exposure>0</exposure></scene>", 2, "greater than 0");
    expect_error("<scene>\n<backColor>1 -2 3</backColor></scene>", 2, "cannot be negative");
    expect_error("<scene>\n<surface type=\"Sphere\">\n<radius>-1</radius></surface></scene>", 3,
                 "radius must be positive");
    expect_error("<scene>\n<surface type=\"Sphere\">\n<radius>0</radius></surface></scene>", 3,
                 "radius must be positive");
    expect_error("<scene>\n<image>0 10</image></scene>", 2, "from 1 to 16384");
    expect_error("<scene>\n<image>100000 10</image></scene>", 2, "from 1 to 16384");
    expect_error("<scene>\n<image>320</image></scene>", 2, "two integers");
    expect_error("<scene>\n<image>320.5 200</image></scene>", 2, "two integers");
    expect_error("<scene>\n<samples>3</samples></scene>", 2, "square number");
    expect_error("<scene>\n<samples>4294967296</samples></scene>", 2, "square number"); /* 65536^2: no overflow */
    expect_error("<scene>\n<samples>1e30</samples></scene>", 2, "square number");
    expect_error("<scene>\n<shader type=\"Phong\">\n<exponent>-1</exponent></shader></scene>", 3, "at least 0");
    expect_error("<scene>\n<shader type=\"Glass\">\n<refractiveIndex>0</refractiveIndex></shader></scene>", 3,
                 "greater than 0");
    expect_error("<scene>\n<light>\n<intensity>-1 0 0</intensity></light></scene>", 3, "cannot be negative");
}

static void test_reference_errors(void **state)
{
    (void)state;
    expect_error("<scene>\n<surface type=\"Sphere\">\n<shader ref=\"nope\"/></surface></scene>", 3,
                 "undefined shader 'nope'");
    expect_error("<scene>\n<shader name=\"a\" type=\"Phong\">\n<texture ref=\"t\"/></shader></scene>", 3,
                 "undefined texture 't'");
    expect_error("<scene>\n<shader name=\"a\" type=\"Phong\"/>\n<shader name=\"a\" type=\"Phong\"/></scene>", 3,
                 "defined twice");
    expect_error("<scene>\n<shader ref=\"a\"/></scene>", 2, "goes inside a <surface>");
}

static void test_file_errors(void **state)
{
    (void)state;
    expect_error("<scene>\n<surface type=\"Mesh\">\n<data>missing.obj</data></surface></scene>", 3,
                 "cannot load mesh 'missing.obj'");
    expect_error("<scene>\n<texture type=\"RepeatTexture\">\n<image>missing.png</image></texture></scene>", 3,
                 "missing.png: cannot read the texture image");
    write_file("not-an-image.png", "plain text");
    expect_error("<scene>\n<texture type=\"RepeatTexture\">\n<image>not-an-image.png</image></texture></scene>", 3,
                 "not-an-image.png: not a PNG file");
    /* broken meshes: the message names the scene line and the mesh's own line */
    const struct {
        const char *name, *text, *words;
    } meshes[] = {
        {"bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "bad.obj:4: face refers to a missing vertex index 7"},
        {"bad2.obj", "v 0 0 zero\n", "bad2.obj:1: missing or malformed number"},
        {"bad3.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "bad3.obj:3: a face needs at least 3 corners"},
        {"bad5.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/0 2/1 3/1\n",
         "bad5.obj:5: face refers to a missing texture coordinate index 0"},
        /* the first bad index is named: the texture coordinate, not the normal */
        {"bad6.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3 2/2/3 3/2/3\n",
         "bad6.obj:4: face refers to a missing texture coordinate index 2"},
        /* a coordinate beyond what `real` holds (only float: 1e39 > FLT_MAX) */
        {"bad7.obj", REAL_MAX < 1e39 ? "v 1e39 0 0\n" : "v 1e400 0 0\n", "bad7.obj:1: missing or malformed number"},
        {"bad4.obj", "v 0 0 0\ncurv 1 2\n", "bad4.obj:2: unknown statement: curv"},
    };
    for (size_t k = 0; k < sizeof meshes / sizeof meshes[0]; k++) {
        char text[256];
        write_file(meshes[k].name, meshes[k].text);
        snprintf(text, sizeof text, "<scene>\n<surface type=\"Mesh\">\n<data>%s</data></surface></scene>",
                 meshes[k].name);
        expect_error(text, 3, meshes[k].words);
    }
    scene s;
    char err[512];
    assert_int_equal(-1, scene_load("/nonexistent/scene.xml", &s, err, sizeof err));
    assert_non_null(strstr(err, "/nonexistent/scene.xml: cannot read the scene"));
}

/* A mesh, texture or scene path that names a directory, a FIFO or a device
 * is refused with that reason, before a byte is read (a FIFO would block,
 * /dev/zero would be read until memory runs out). */
static void test_paths_that_are_not_regular_files(void **state)
{
    (void)state;
    char fifo[256], sub[256];
    snprintf(fifo, sizeof fifo, "%s/fifo", folder);
    snprintf(sub, sizeof sub, "%s/sub", folder);
    assert_int_equal(0, mkfifo(fifo, 0600));
    assert_int_equal(0, mkdir(sub, 0700));
    static const struct {
        const char *path, *kind;
    } bad[] = {{"/dev/zero", "a character device"}, {"fifo", "a FIFO"}, {"sub", "a directory"}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char text[256], words[128];
        snprintf(text, sizeof text, "<scene>\n<surface type=\"Mesh\">\n<data>%s</data></surface></scene>", bad[k].path);
        snprintf(words, sizeof words, "the mesh is %s, not a regular file", bad[k].kind);
        expect_error(text, 3, words);
        snprintf(text, sizeof text, "<scene>\n<texture type=\"ClampTexture\">\n<image>%s</image></texture></scene>",
                 bad[k].path);
        snprintf(words, sizeof words, "the texture image is %s, not a regular file", bad[k].kind);
        expect_error(text, 3, words);
    }
    scene s;
    char err[512];
    assert_int_equal(-1, scene_load(fifo, &s, err, sizeof err));
    assert_non_null(strstr(err, "the scene is a FIFO, not a regular file"));
    assert_int_equal(-1, scene_load(sub, &s, err, sizeof err));
    assert_non_null(strstr(err, "the scene is a directory, not a regular file"));
    unlink(fifo);
    rmdir(sub);
}

/* A texture is decoded in full when the scene is read, and its texels kept:
 * a PNG whose header is valid but whose pixels are cut short is refused. */
static void test_texture_images_are_decoded_in_full(void **state)
{
    (void)state;
    enum { W = 32, H = 24 };
    unsigned char rgb[W * H * 3];
    unsigned state_bits = 12345; /* noise, so that the PNG does not compress below 100 bytes */
    for (size_t k = 0; k < sizeof rgb; k++) {
        state_bits = state_bits * 1103515245u + 12345u;
        rgb[k] = (unsigned char)(state_bits >> 16);
    }
    char path[256];
    snprintf(path, sizeof path, "%s/noise.png", folder);
    assert_int_not_equal(0, stbi_write_png(path, W, H, 3, rgb, W * 3));
    const char *text = "<scene>\n<texture name=\"n\" type=\"RepeatTexture\">\n<image>noise.png</image></texture></scene>";
    scene s;
    char err[1024] = "";
    if (load_text(text, &s, err, sizeof err) != 0)
        fail_msg("%s", err);
    assert_int_equal(1, s.n_textures);
    const texture_image *t = &s.textures[0].image;
    assert_int_equal(W, t->width);
    assert_int_equal(H, t->height);
    assert_memory_equal(rgb, t->rgb, sizeof rgb); /* row 0 is the file's top row */
    color c = texture_image_texel(t, 5, 7);
    /* byte / 255, one rounding of a quotient: within REAL_EPSILON / 2 relative */
    assert_close(rgb[(7 * W + 5) * 3 + 1] / 255.0, c.g, REAL_EPSILON);
    /* an index outside the image reads the edge texel nearest to it (and says so on stderr) */
    assert_close(rgb[(7 * W + 0) * 3 + 1] / 255.0, texture_image_texel(t, -1, 7).g, REAL_EPSILON);
    assert_close(rgb[((H - 1) * W + W - 1) * 3] / 255.0, texture_image_texel(t, W, H + 5).r, REAL_EPSILON);
    scene_free(&s);
    /* the same file cut to 100 bytes: its header still reads as 32 x 24 */
    FILE *f = fopen(path, "r+b");
    assert_non_null(f);
    assert_int_equal(0, ftruncate(fileno(f), 100));
    fclose(f);
    expect_error(text, 3, "noise.png: the image is broken");
    /* not a PNG: refused before decoding (stb_image's other decoders accept files cut short) */
    unsigned char bmp[54 + 4] = {'B', 'M'};
    f = fopen(path, "wb");
    assert_non_null(f);
    fwrite(bmp, 1, sizeof bmp, f);
    fclose(f);
    expect_error(text, 3, "noise.png: not a PNG file");
    /* a chunk that claims more than the file holds (an IDAT of 0x6300000c
     * bytes in a 57-byte file): refused before stb_image allocates for it */
    static const unsigned char claims[] = {
        0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0, 0, 2, 0, 0, 0, 2,
        8, 2, 0, 0, 0, 0xfd, 0xd4, 0x9a, 0x73, 0x63, 0, 0, 0x0c, 'I', 'D', 'A', 'T', 0, 0, 0, 0, 0, 0, 0, 0,
        'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    texture_image broken;
    char problem[256];
    assert_int_equal(-1, texture_image_decode(claims, sizeof claims, &broken, problem, sizeof problem));
    if (!strstr(problem, "chunk 'IDAT' claims 1660944396 bytes, more than the file holds"))
        fail_msg("%s", problem);
    assert_null(broken.rgb);
    /* an empty first IDAT chunk: stb_image would add 0 to a null pointer */
    static const unsigned char empty_idat[] = {
        0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0, 0, 2, 0, 0, 0, 2,
        8, 2, 0, 0, 0, 0xfd, 0xd4, 0x9a, 0x73, 0, 0, 0, 0, 'I', 'D', 'A', 'T', 0x35, 0xaf, 0x06, 0x1e,
        0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    assert_int_equal(-1, texture_image_decode(empty_idat, sizeof empty_idat, &broken, problem, sizeof problem));
    if (!strstr(problem, "its first IDAT chunk is empty"))
        fail_msg("%s", problem);
}

/* Writes an OBJ file of `lines` copies of `line` after a triangle's vertices. */
static void write_obj_lines(const char *name, const char *line, int lines)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\n", f);
    for (int k = 0; k < lines; k++)
        fputs(line, f);
    fclose(f);
}

/* One line, one face, one file: each has a limit, named when it is passed. */
static void test_limits_of_one_line_face_and_file(void **state)
{
    (void)state;
    /* a line of MESH_MAX_LINE_BYTES + 1 characters: a comment, harmless but for its length */
    char *long_line = malloc(MESH_MAX_LINE_BYTES + 3);
    assert_non_null(long_line);
    memset(long_line, ' ', MESH_MAX_LINE_BYTES + 1);
    long_line[0] = '#';
    strcpy(long_line + MESH_MAX_LINE_BYTES + 1, "\n");
    write_obj_lines("long.obj", long_line, 1);
    long_line[MESH_MAX_LINE_BYTES] = '\n'; /* one shorter: accepted (then "no faces") */
    long_line[MESH_MAX_LINE_BYTES + 1] = '\0';
    write_obj_lines("long-ok.obj", long_line, 1);
    free(long_line);
    expect_error("<scene>\n<surface type=\"Mesh\">\n<data>long.obj</data></surface></scene>", 3,
                 "long.obj:4: the line is longer than 65536 bytes (the limit of one line)");
    expect_error("<scene>\n<surface type=\"Mesh\">\n<data>long-ok.obj</data></surface></scene>", 3,
                 "long-ok.obj: the mesh has no faces");
    /* a face of MESH_MAX_CORNERS + 1 corners */
    char face[MESH_MAX_CORNERS * 3 + 8] = "f";
    for (int k = 0; k <= MESH_MAX_CORNERS; k++)
        strcat(face, k % 3 == 0 ? " 1" : k % 3 == 1 ? " 2" : " 3");
    strcat(face, "\n");
    write_obj_lines("corners.obj", face, 1);
    expect_error("<scene>\n<surface type=\"Mesh\">\n<data>corners.obj</data></surface></scene>", 3,
                 "corners.obj:4: a face has more than 1024 corners (the limit of one face)");
    /* a NUL byte: not a text file */
    char path[256];
    snprintf(path, sizeof path, "%s/nul.obj", folder);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fwrite("v 0 0 0\nv 1\0 0 0\n", 1, 18, f);
    fclose(f);
    expect_error("<scene>\n<surface type=\"Mesh\">\n<data>nul.obj</data></surface></scene>", 3,
                 "nul.obj:2: the line holds a NUL byte");
    /* files larger than their limits: sparse, so nothing is written */
    snprintf(path, sizeof path, "%s/huge.obj", folder);
    f = fopen(path, "w");
    assert_non_null(f);
    assert_int_equal(0, ftruncate(fileno(f), (off_t)MESH_MAX_FILE_BYTES + 1));
    fclose(f);
    expect_error("<scene>\n<surface type=\"Mesh\">\n<data>huge.obj</data></surface></scene>", 3,
                 "the mesh is 268435457 bytes, more than the 268435456 one such file may hold");
    snprintf(path, sizeof path, "%s/huge.xml", folder);
    f = fopen(path, "w");
    assert_non_null(f);
    assert_int_equal(0, ftruncate(fileno(f), (off_t)SCENE_MAX_FILE_BYTES + 1));
    fclose(f);
    scene s;
    char err[512];
    assert_int_equal(-1, scene_load(path, &s, err, sizeof err));
    assert_non_null(strstr(err, "the scene is 67108865 bytes, more than the 67108864"));
    unlink(path);
    snprintf(path, sizeof path, "%s/huge.obj", folder);
    unlink(path);
}

static void test_obj_relative_indices_and_slashes(void **state)
{
    (void)state;
    write_file("rel.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//-1 -2//-1 -1//-1\n");
    mesh m;
    char err[512], path[256];
    snprintf(path, sizeof path, "%s/rel.obj", folder);
    if (mesh_load(path, &m, err, sizeof err) != 0)
        fail_msg("%s", err);
    assert_int_equal(1, m.n_faces);
    assert_int_equal(0, m.faces[0].v[0]);
    assert_int_equal(2, m.faces[0].v[2]);
    assert_int_equal(-1, m.faces[0].vt[1]);
    assert_int_equal(0, m.faces[0].vn[1]);
    mesh_free(&m);
}

/* What exporters write around the faces: a UTF-8 byte order mark, tabs
 * after the keywords, CRLF line ends, a bare `g` and `s off`, lines and
 * points (no area: nothing for a ray to hit).  The two faces are read as
 * written, nothing else. */
static void test_obj_as_exporters_write_it(void **state)
{
    (void)state;
    write_file("exported.obj", "\xef\xbb\xbf# exported\r\nmtllib a.mtl\r\no thing\r\ng\r\ns off\r\n"
                               "v\t0.5 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 0 0 1\r\nvt\t0.25 0.75\r\n"
                               "usemtl m\r\nf\t1/1 2/1 3/1\r\nl 1 2\r\np 4\r\n\r\nf 4 3 2\r\n");
    mesh m;
    char err[512], path[256];
    snprintf(path, sizeof path, "%s/exported.obj", folder);
    if (mesh_load(path, &m, err, sizeof err) != 0)
        fail_msg("%s", err);
    assert_int_equal(4, m.n_positions);
    assert_int_equal(2, m.n_faces);
    assert_true(m.positions[0].x == 0.5);
    assert_true(m.uvs[0].u == 0.25 && m.uvs[0].v == 0.75);
    assert_int_equal(3, m.faces[1].v[0]);
    assert_int_equal(1, m.faces[1].v[2]);
    mesh_free(&m);
    /* a byte order mark is taken at the start of the file only */
    write_file("late-mark.obj", "v 0 0 0\n\xef\xbb\xbfv 1 0 0\n");
    snprintf(path, sizeof path, "%s/late-mark.obj", folder);
    assert_int_equal(-1, mesh_load(path, &m, err, sizeof err));
    assert_non_null(strstr(err, "late-mark.obj:2: unknown statement"));
}

/* Every scene of the course parses, with spot checks of what it holds. */
static void test_cornell_corpus_parses(void **state)
{
    (void)state;
    const char *data = cornell_data();
    if (!data) {
        print_message("the Cornell corpus (../shared/cornell) is absent: skipped\n");
        skip();
    }
    static const struct {
        const char *file;
        int width, n_surfaces, n_lights, faces; /* faces of the first mesh, or 0 */
    } corpus[] = {
        {"bunny-norms.xml", 450, 2, 1, 4968},    {"bunny.xml", 450, 2, 1, 4968},
        {"bunny2.xml", 450, 2, 1, 0},            {"diagnostic.xml", 0, 0, 0, 0},
        {"earth-eclipse-textured.xml", 2048, 2, 1, 0}, {"earth.xml", 0, 0, 0, 0},
        {"one-sphere-rgb-normals.xml", 0, 1, 0, 0}, {"one-sphere.xml", 0, 1, 0, 0},
        {"teapot.xml", 0, 0, 0, 6320},           {"two-boxes-rgb-normals.xml", 320, 2, 2, 0},
        {"two-boxes.xml", 320, 2, 2, 0},         {"wire-box-orthographic.xml", 320, 21, 3, 0},
        {"wire-box.xml", 320, 21, 3, 0},
    };
    for (size_t k = 0; k < sizeof corpus / sizeof corpus[0]; k++) {
        char path[512], err[1024];
        snprintf(path, sizeof path, "%s/scenes/ray1/%s", data, corpus[k].file);
        scene s;
        if (scene_load(path, &s, err, sizeof err) != 0)
            fail_msg("%s", err);
        assert_true(s.has_camera);
        if (corpus[k].width)
            assert_int_equal(corpus[k].width, s.width);
        if (corpus[k].n_surfaces)
            assert_int_equal(corpus[k].n_surfaces, s.n_surfaces);
        if (corpus[k].n_lights)
            assert_int_equal(corpus[k].n_lights, s.n_lights);
        if (corpus[k].faces) {
            assert_true(s.n_meshes > 0);
            assert_int_equal(corpus[k].faces, s.meshes[0].n_faces);
        }
        scene_free(&s);
    }
}

/* A stage without the grid is warned of a scene with more than
 * SCENE_MANY_TRIANGLES triangles it tests (common/scene_cost.h): Triangle
 * surfaces always, mesh faces when it models meshes. */
static void test_cost_note_counts_the_triangles_a_stage_tests(void **state)
{
    (void)state;
    mesh big = {.n_faces = SCENE_MANY_TRIANGLES}; /* only the count is read */
    scene_surface surfaces[] = {{.kind = SURFACE_MESH, .mesh = 0}, {.kind = SURFACE_SPHERE},
                                {.kind = SURFACE_TRIANGLE}, {.kind = SURFACE_BOX}};
    scene s;
    scene_init(&s);
    s.meshes = &big;
    s.n_meshes = 1;
    s.surfaces = surfaces;
    s.n_surfaces = 2; /* the mesh and the sphere: exactly at the limit */
    const unsigned all = FEATURE_TRIANGLES | FEATURE_MESHES | FEATURE_SPHERES | FEATURE_BOXES;
    char note[256] = "x";
    assert_int_equal(SCENE_MANY_TRIANGLES, scene_triangles(&s, all));
    scene_cost_note(&s, all, note, sizeof note);
    assert_string_equal("", note);
    s.n_surfaces = 4; /* and one Triangle: one more than the limit */
    assert_int_equal(SCENE_MANY_TRIANGLES + 1, scene_triangles(&s, all));
    scene_cost_note(&s, all, note, sizeof note);
    char count[32];
    snprintf(count, sizeof count, "%d triangles", SCENE_MANY_TRIANGLES + 1);
    if (strncmp(note, count, strlen(count)) != 0 || !strstr(note, "chapter 11"))
        fail_msg("the note does not start with '%s' and name chapter 11: '%s'", count, note);
    /* Chapter 03 ignores meshes: one triangle to test. */
    assert_int_equal(1, scene_triangles(&s, FEATURE_TRIANGLES | FEATURE_SPHERES));
    scene_cost_note(&s, FEATURE_TRIANGLES | FEATURE_SPHERES, note, sizeof note);
    assert_string_equal("", note);
}

static const graded_test tests[] = {
    GRADED(test_full_scene_values, 0),
    GRADED(test_defaults_of_an_empty_scene, 0),
    GRADED(test_structure_errors, 0),
    GRADED(test_number_errors, 0),
    GRADED(test_reference_errors, 0),
    GRADED(test_file_errors, 0),
    GRADED(test_obj_relative_indices_and_slashes, 0),
    GRADED(test_obj_as_exporters_write_it, 0),
    GRADED(test_paths_that_are_not_regular_files, 0),
    GRADED(test_texture_images_are_decoded_in_full, 0),
    GRADED(test_limits_of_one_line_face_and_file, 0),
    GRADED(test_cornell_corpus_parses, 0),
    GRADED(test_cost_note_counts_the_triangles_a_stage_tests, 0),
};

int main(int argc, char **argv)
{
    if (make_folder(NULL) != 0)
        return 1;
    int failed = suite_main("common_scene", tests, sizeof tests / sizeof tests[0], argc, argv);
    remove_folder(NULL);
    return failed;
}
