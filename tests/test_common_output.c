/* Writing the image (common/png_write.h): a new path or a regular file is
 * written whole; anything else at the path is refused and left alone. */
#define _XOPEN_SOURCE 700 /* mknod */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <stb_image.h>

#include "png_write.h"
#include "suite.h"

static char folder[64];

static const char *in_folder(const char *name)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    return path;
}

/* A 3x2 image of radiances that display_encode maps to known bytes: L = 1
 * is 255, L = 0 is 0 (docs/scenes.md's encoding at exposure 1). */
static void make_image(image *img)
{
    assert_int_equal(0, image_init(img, 3, 2));
    *image_at(img, 0, 0) = color_make(1, 0, 0); /* bottom left: the last row of the PNG */
    *image_at(img, 2, 1) = color_make(0, 1, 1); /* top right: the first row */
}

static void test_writes_a_new_path_and_replaces_a_file(void **state)
{
    (void)state;
    image img;
    make_image(&img);
    char err[512] = "";
    const char *path = in_folder("new.png");
    if (png_write(&img, 1, path, err, sizeof err) != 0)
        fail_msg("%s", err);
    FILE *f = fopen(path, "w"); /* now a regular file with other content: replaced */
    assert_non_null(f);
    fputs("old", f);
    fclose(f);
    if (png_write(&img, 1, path, err, sizeof err) != 0)
        fail_msg("%s", err);
    int w, h, n;
    unsigned char *rgb = stbi_load(path, &w, &h, &n, 3);
    assert_non_null(rgb);
    assert_int_equal(3, w);
    assert_int_equal(2, h);
    assert_int_equal(255, rgb[(1 * 3 + 0) * 3 + 0]); /* (0, 0) is in the PNG's row 1 */
    assert_int_equal(0, rgb[(1 * 3 + 0) * 3 + 1]);
    assert_int_equal(255, rgb[(0 * 3 + 2) * 3 + 2]); /* (2, 1) is in row 0 */
    stbi_image_free(rgb);
    image_free(&img);
}

/* A FIFO at the output path was once opened and replaced; now it, a
 * directory and a device are refused, and each is still there afterwards. */
static void test_refuses_what_is_not_a_regular_file(void **state)
{
    (void)state;
    image img;
    make_image(&img);
    char fifo[128], dir[128];
    snprintf(fifo, sizeof fifo, "%s", in_folder("fifo.png"));
    snprintf(dir, sizeof dir, "%s", in_folder("dir.png"));
    assert_int_equal(0, mkfifo(fifo, 0600));
    assert_int_equal(0, mkdir(dir, 0700));
    static const char *const kinds[] = {"a FIFO", "a directory", "a character device"};
    /* A device of our own (when allowed to make one), never /dev/null: a
     * renderer without this check once replaced /dev/null with a file. */
    char device[128];
    snprintf(device, sizeof device, "%s", in_folder("zero.png"));
    int n = mknod(device, S_IFCHR | 0600, makedev(1, 5)) == 0 ? 3 : 2;
    if (n == 2)
        print_message("cannot make a device node here: the device case is not tried\n");
    const char *paths[] = {fifo, dir, device};
    for (int k = 0; k < n; k++) {
        char err[512] = "";
        int status = png_write(&img, 1, paths[k], err, sizeof err);
        if (status != -1)
            fail_msg("%s: written (status %d)", paths[k], status);
        char words[sizeof device + 64]; /* a path of up to 127 characters and the words */
        snprintf(words, sizeof words, "%s: not written: it is %s", paths[k], kinds[k]);
        if (!strstr(err, words))
            fail_msg("expected '%s' in '%s'", words, err);
        assert_int_equal(-1, png_check_output(paths[k], err, sizeof err));
    }
    struct stat st;
    assert_int_equal(0, stat(fifo, &st));
    assert_true(S_ISFIFO(st.st_mode)); /* left alone */
    assert_int_equal(0, stat(dir, &st));
    assert_true(S_ISDIR(st.st_mode));
    if (n == 3) {
        assert_int_equal(0, stat(device, &st));
        assert_true(S_ISCHR(st.st_mode));
        unlink(device);
    }
    char err[512];
    assert_int_equal(0, png_check_output(in_folder("absent.png"), err, sizeof err));
    unlink(fifo);
    rmdir(dir);
    image_free(&img);
}

static const graded_test tests[] = {
    GRADED(test_writes_a_new_path_and_replaces_a_file, 0),
    GRADED(test_refuses_what_is_not_a_regular_file, 0),
};

int main(int argc, char **argv)
{
    strcpy(folder, "/tmp/rt-output-XXXXXX");
    if (!mkdtemp(folder))
        return 1;
    int failed = suite_main("common_output", tests, sizeof tests / sizeof tests[0], argc, argv);
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", folder);
    return system(command) == 0 ? failed : 1;
}
