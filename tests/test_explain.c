/* --explain X,Y (common/explain.h) against the image, for every renderer of
 * this build (double, float or sanitizer): the explained pixel value,
 * encoded, is the byte the PNG holds at (X, Y), for several pixels of each
 * chapter's built-in scene; and the PNG is the one rendered without
 * --explain, byte for byte.
 *
 * The renderers are found beside this suite: BUILD/tests/test_explain runs
 * BUILD/NN_name/render. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stb_image.h>

#include "display.h"
#include "explain_tree.h"
#include "suite.h"

#define WIDTH 40
#define HEIGHT 30

/* The pixels explained in every image: its corners, its centre, and some between. */
static const int pixels[][2] = {{0, 0}, {WIDTH - 1, HEIGHT - 1}, {WIDTH / 2, HEIGHT / 2}, {9, 21}, {31, 7}, {13, 10}};

static char build[512]; /* BUILD/ */
static char scratch[64];

static int setup(void **state)
{
    (void)state;
    char self[sizeof build];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0)
        return -1;
    self[n] = '\0';
    char *slash = strrchr(self, '/'); /* BUILD/tests/test_explain */
    if (!slash)
        return -1;
    *slash = '\0';
    slash = strrchr(self, '/');
    if (!slash)
        return -1;
    slash[1] = '\0';
    snprintf(build, sizeof build, "%s", self);
    snprintf(scratch, sizeof scratch, "/tmp/test_explain-XXXXXX");
    return mkdtemp(scratch) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char command[sizeof scratch + 16];
    snprintf(command, sizeof command, "rm -rf '%s'", scratch);
    return system(command) == 0 ? 0 : -1;
}

static int run(const char *command)
{
    int status = system(command);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The whole of a file, NUL-terminated; NULL when it cannot be read. */
static char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *data = NULL;
    size_t used = 0, capacity = 0, got;
    do {
        if (used + 4096 + 1 > capacity) {
            capacity = 2 * capacity + 4096 + 1;
            char *bigger = realloc(data, capacity);
            if (!bigger)
                break;
            data = bigger;
        }
        got = fread(data + used, 1, 4096, f);
        used += got;
    } while (got > 0);
    fclose(f);
    if (data)
        data[used] = '\0';
    *size = used;
    return data;
}

/* Renders chapter `name`'s built-in scene with --explain X,Y and -n samples, and checks the explanation
 * against the PNG it wrote and against `plain`, the PNG rendered without --explain. */
static void check_pixel(const char *name, int x, int y, int samples, const char *plain)
{
    char png[256], json[256], text[256], command[2048];
    snprintf(png, sizeof png, "%s/%s-%d-%d.png", scratch, name, x, y);
    snprintf(json, sizeof json, "%s/%s-%d-%d.json", scratch, name, x, y);
    snprintf(text, sizeof text, "%s/%s-%d-%d.txt", scratch, name, x, y);
    snprintf(command, sizeof command, "%s%s/render -q -j1 -s %dx%d -n %d -o '%s' --explain %d,%d --explain-json '%s' >'%s'",
             build, name, WIDTH, HEIGHT, samples, png, x, y, json, text);
    assert_int_equal(0, run(command));

    size_t size;
    char *tree = slurp(json, &size);
    assert_non_null(tree);
    const char *pixel = strstr(tree, "\"pixel\": {");
    assert_non_null(pixel);
    int px, py, bytes[3];
    double L[3], exposure;
    const char *at = strstr(pixel, "\"L\": [");
    assert_non_null(at);
    assert_int_equal(2, sscanf(pixel, "\"pixel\": {\"x\": %d, \"y\": %d", &px, &py));
    assert_int_equal(7, sscanf(at, "\"L\": [%lf, %lf, %lf], \"exposure\": %lf, \"bytes\": [%d, %d, %d]", &L[0], &L[1],
                               &L[2], &exposure, &bytes[0], &bytes[1], &bytes[2]));
    assert_int_equal(x, px);
    assert_int_equal(y, py);
    assert_non_null(strstr(tree, "\"complete\": true"));
    free(tree);

    int w, h, channels;
    unsigned char *image = stbi_load(png, &w, &h, &channels, 3);
    assert_non_null(image);
    assert_int_equal(WIDTH, w);
    assert_int_equal(HEIGHT, h);
    for (int c = 0; c < 3; c++) {
        /* L is printed with 17 digits: the real it was, exactly, in either build */
        assert_int_equal(display_encode((real)L[c], (real)exposure), bytes[c]);
        assert_int_equal(image[3 * (y * WIDTH + x) + c], bytes[c]);
    }
    stbi_image_free(image);

    char *said = slurp(text, &size);
    assert_non_null(said);
    assert_non_null(strstr(said, ": the same\n"));
    free(said);

    size_t a_size, b_size;
    char *a = slurp(png, &a_size), *b = slurp(plain, &b_size);
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(b_size, a_size);
    assert_memory_equal(b, a, a_size);
    free(a);
    free(b);
}

/* Every chapter's renderer, each at every pixel of `pixels`. */
static void test_every_renderer(void **state)
{
    (void)state;
    int renderers = 0;
    for (int chapter = 1; chapter <= 99; chapter++) {
        char command[sizeof build + 64], name[64];
        snprintf(command, sizeof command, "cd '%s' && ls -d %02d_*/render 2>/dev/null", build, chapter);
        FILE *list = popen(command, "r");
        assert_non_null(list);
        bool found = fgets(name, sizeof name, list) != NULL;
        pclose(list);
        if (!found)
            continue;
        *strchr(name, '/') = '\0';
        char plain[256], render[2048];
        snprintf(plain, sizeof plain, "%s/%s-plain.png", scratch, name);
        snprintf(render, sizeof render, "%s%s/render -q -j1 -s %dx%d -o '%s'", build, name, WIDTH, HEIGHT, plain);
        assert_int_equal(0, run(render));
        for (size_t k = 0; k < sizeof pixels / sizeof pixels[0]; k++)
            check_pixel(name, pixels[k][0], pixels[k][1], 1, plain);
        renderers++;
    }
    assert_int_equal(11, renderers);
}

/* With 4 samples a pixel, the explained value is the mean of the four explained samples. */
static void test_samples(void **state)
{
    (void)state;
    const char *names[] = {"06_shadows", "09_refraction"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        char plain[256], render[2048];
        snprintf(plain, sizeof plain, "%s/%s-plain-4.png", scratch, names[k]);
        snprintf(render, sizeof render, "%s%s/render -q -j1 -s %dx%d -n 4 -o '%s'", build, names[k], WIDTH, HEIGHT,
                 plain);
        assert_int_equal(0, run(render));
        check_pixel(names[k], WIDTH / 2, HEIGHT / 2, 4, plain);
        check_pixel(names[k], 9, 21, 4, plain);
    }
}

/* A pixel outside the image is refused before rendering, naming the image's size. */
static void test_outside(void **state)
{
    (void)state;
    char command[2048], out[256];
    snprintf(out, sizeof out, "%s/outside.png", scratch);
    snprintf(command, sizeof command, "%s05_lambert/render -q -s %dx%d -o '%s' --explain %d,0 2>'%s.err'", build, WIDTH,
             HEIGHT, out, WIDTH, out);
    assert_int_equal(2, run(command));
    assert_int_equal(-1, access(out, F_OK)); /* no image */
    char err[sizeof out + 8];
    snprintf(err, sizeof err, "%s.err", out);
    size_t size;
    char *said = slurp(err, &size);
    assert_non_null(said);
    assert_non_null(strstr(said, "no such pixel in a 40x30 image"));
    free(said);
}

/* A tree too large to hold: one pixel of 65536 samples, each a subtree
 * (glass in glass at --min-weight=0 grows as fast, doubling at every
 * depth).  Chapter 01's renderer, whose tree comes from the given code
 * whatever a student's exercises hold.  The explanation stops at
 * EXPLAIN_MAX_NODES entries and says so, and still ends with the pixel's
 * value and its bytes, the image's own. */
static void test_tree_too_large(void **state)
{
    (void)state;
    char text[256], json[256], png[256], command[2048];
    snprintf(text, sizeof text, "%s/many-samples.txt", scratch);
    snprintf(json, sizeof json, "%s/many-samples.json", scratch);
    snprintf(png, sizeof png, "%s/many-samples.png", scratch);
    snprintf(command, sizeof command,
             "%s01_camera_rays/render -q -j1 -s 1x1 -n 65536 -o '%s' --explain 0,0 --explain-json '%s' >'%s'", build,
             png, json, text);
    assert_int_equal(0, run(command));
    size_t size;
    char *said = slurp(text, &size);
    assert_non_null(said);
    long lines = 0;
    for (const char *c = said; *c; c++)
        lines += *c == '\n';
    /* each entry prints its line, a ray one more with its outcome */
    if (lines < EXPLAIN_MAX_NODES || lines > 2L * EXPLAIN_MAX_NODES + 10)
        fail_msg("the explanation of 65536 samples has %ld lines: expected from %d (one per entry) to %d", lines,
                 EXPLAIN_MAX_NODES, 2 * EXPLAIN_MAX_NODES + 10);
    assert_non_null(strstr(said, "(the explanation stops here: it holds at most 100000 rays, tests and terms"));
    assert_non_null(strstr(said, ": the same\n"));
    free(said);
    char *tree = slurp(json, &size);
    assert_non_null(tree);
    assert_non_null(strstr(tree, "\"complete\": false"));
    free(tree);
}

static const graded_test tests[] = {
    GRADED(test_every_renderer, 1),
    GRADED(test_samples, 1),
    GRADED(test_outside, 1),
    GRADED(test_tree_too_large, 1),
};

int main(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    if (setup(NULL) != 0) {
        fprintf(stderr, "test_explain: cannot find the build folder or make a scratch folder\n");
        return 1;
    }
    int status = suite_main("explain", tests, sizeof tests / sizeof tests[0], argc, argv);
    teardown(NULL);
    return status;
}
