/* Display encoding (docs/scenes.md) and the atomic PNG writer. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb_image.h>

#include "display.h"
#include "png_write.h"
#include "suite.h"

static void test_encode_black_white_and_clamp(void **state)
{
    (void)state;
    assert_int_equal(0, display_encode(0, 1));
    assert_int_equal(255, display_encode(1, 1));
    assert_int_equal(255, display_encode(1000, 1)); /* clamp */
    assert_int_equal(0, display_encode(-1, 1));     /* clamp below */
    assert_int_equal(0, display_encode((real)NAN, 1));
    assert_int_equal(255, display_encode(REAL_INFINITY, 1));
}

static void test_encode_gamma(void **state)
{
    (void)state;
    /* 255 * 0.5^(1/2.2) = 186.0749...: rounds to 186 */
    assert_int_equal(186, display_encode((real)0.5, 1));
    /* exposure multiplies before the gamma: 0.25 * 2 = 0.5 */
    assert_int_equal(186, display_encode((real)0.25, 2));
    /* 255 * 0.01^(1/2.2) = 31.35...: 31 */
    assert_int_equal(31, display_encode((real)0.01, 1));
    /* (k/255)^2.2 encodes back to k for every byte k: the round trip is exact */
    for (int k = 0; k < 256; k++) {
        double L = pow(k / 255.0, 2.2);
        assert_int_equal(k, display_encode((real)L, 1));
    }
}

static void test_encode_rounds_half_up(void **state)
{
    (void)state;
    /* L whose encoding is 100.5/255 sits on the rounding boundary; a hair
     * above it must give 101 and a hair below 100. */
    double L = pow(100.5 / 255.0, 2.2);
    assert_int_equal(101, display_encode((real)(L * (1 + 1e-5)), 1));
    assert_int_equal(100, display_encode((real)(L * (1 - 1e-5)), 1));
}

/* A fresh, empty folder for one test. */
static char *temp_folder(void)
{
    char *folder = strdup("/tmp/rt-png-XXXXXX");
    assert_non_null(mkdtemp(folder));
    return folder;
}

static int count_entries(const char *folder)
{
    DIR *dir = opendir(folder);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(dir)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            n++;
    closedir(dir);
    return n;
}

static void test_png_round_trip_with_rows_flipped(void **state)
{
    (void)state;
    char *folder = temp_folder();
    char path[256];
    snprintf(path, sizeof path, "%s/a.png", folder);
    image img;
    assert_int_equal(0, image_init(&img, 3, 2));
    *image_at(&img, 0, 0) = color_make(1, 0, 0); /* bottom-left: red */
    *image_at(&img, 2, 1) = color_make(0, 0, 1); /* top-right: blue */
    *image_at(&img, 1, 1) = color_make((real)0.5, (real)0.5, (real)0.5);
    char err[256] = "";
    assert_int_equal(0, png_write(&img, 1, path, err, sizeof err));
    int w, h, channels;
    unsigned char *bytes = stbi_load(path, &w, &h, &channels, 3);
    assert_non_null(bytes);
    assert_int_equal(3, w);
    assert_int_equal(2, h);
    /* PNG rows go top first: row 0 is j = 1 */
    const unsigned char top_right[3] = {0, 0, 255}, bottom_left[3] = {255, 0, 0}, grey[3] = {186, 186, 186};
    assert_memory_equal(top_right, bytes + (0 * 3 + 2) * 3, 3);
    assert_memory_equal(grey, bytes + (0 * 3 + 1) * 3, 3);
    assert_memory_equal(bottom_left, bytes + (1 * 3 + 0) * 3, 3);
    stbi_image_free(bytes);
    struct stat st;
    assert_int_equal(0, stat(path, &st));
    assert_int_equal(0644, st.st_mode & 0777);
    assert_int_equal(1, count_entries(folder)); /* no temporary file left */
    image_free(&img);
    unlink(path);
    rmdir(folder);
    free(folder);
}

static void test_png_replaces_existing_file_whole(void **state)
{
    (void)state;
    char *folder = temp_folder();
    char path[256];
    snprintf(path, sizeof path, "%s/b.png", folder);
    FILE *f = fopen(path, "w");
    fputs("an old file that is not a PNG", f);
    fclose(f);
    image img;
    assert_int_equal(0, image_init(&img, 4, 4));
    char err[256];
    assert_int_equal(0, png_write(&img, 1, path, err, sizeof err));
    int w, h, channels;
    assert_int_equal(1, stbi_info(path, &w, &h, &channels));
    assert_int_equal(4, w);
    assert_int_equal(1, count_entries(folder));
    image_free(&img);
    unlink(path);
    rmdir(folder);
    free(folder);
}

static void test_png_failure_leaves_nothing_and_names_path(void **state)
{
    (void)state;
    char *folder = temp_folder();
    image img;
    assert_int_equal(0, image_init(&img, 2, 2));
    char err[512] = "";
    /* a folder that does not exist: the temporary file cannot be created */
    char path[256];
    snprintf(path, sizeof path, "%s/missing/c.png", folder);
    assert_int_equal(-1, png_write(&img, 1, path, err, sizeof err));
    assert_non_null(strstr(err, path));
    /* the destination is a folder: the rename fails, the folder survives
     * and the complete temporary file is removed */
    snprintf(path, sizeof path, "%s/d.png", folder);
    assert_int_equal(0, mkdir(path, 0755));
    assert_int_equal(-1, png_write(&img, 1, path, err, sizeof err));
    assert_non_null(strstr(err, path));
    struct stat st;
    assert_int_equal(0, stat(path, &st));
    assert_true(S_ISDIR(st.st_mode));
    assert_int_equal(1, count_entries(folder));
    rmdir(path);
    rmdir(folder);
    free(folder);
    image_free(&img);
}

static const graded_test tests[] = {
    GRADED(test_encode_black_white_and_clamp, 0),
    GRADED(test_encode_gamma, 0),
    GRADED(test_encode_rounds_half_up, 0),
    GRADED(test_png_round_trip_with_rows_flipped, 0),
    GRADED(test_png_replaces_existing_file_whole, 0),
    GRADED(test_png_failure_leaves_nothing_and_names_path, 0),
};
SUITE_MAIN("common_display", tests)
