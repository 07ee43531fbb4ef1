/* lab_09_refraction.c - chapter 09's lab: the Fresnel table (not graded).
 *
 * fresnel_table prints R to 6 decimals, so a value is read back within
 * 5e-7 of what was computed; the values checked are exact fractions
 * ((eta - 1) / (eta + 1))^2 = 0.04 head on, 1 past the critical angle
 * asin(1 / 1.5) = 41.81 degrees, and 1 at grazing incidence into glass. */
#include <stdio.h>
#include <string.h>

#include "suite.h"

#include "09_refraction/lab/fresnel_table.h"

enum { STEPS = 90 * 8 };

static void test_fresnel_table(void **state)
{
    (void)state;
    static char text[1 << 16];
    FILE *out = fmemopen(text, sizeof text - 1, "w");
    assert_non_null(out);
    assert_int_equal(0, fresnel_table(out, (real)1.5, STEPS));
    fclose(out);
    char *line = strtok(text, "\n");
    assert_non_null(line);
    assert_true(line[0] == '#');
    const double critical = 41.8103148958;
    int lines = 0;
    double last_in = 0;
    while ((line = strtok(NULL, "\n")) != NULL) {
        double angle, r[5];
        assert_int_equal(6, sscanf(line, "%lf %lf %lf %lf %lf %lf", &angle, &r[0], &r[1], &r[2], &r[3], &r[4]));
        assert_close(90.0 * lines / STEPS, angle, 5e-5);
        if (lines == 0)
            for (int k = 0; k < 5; k++)
                assert_close(0.04, r[k], 5e-7); /* head on: R_0 every way */
        if (angle > critical)
            for (int k = 2; k < 5; k++)
                assert_close(1, r[k], 0); /* out of glass past theta_c: total internal reflection */
        if (angle < critical - 0.2)
            assert_true(r[2] < 1 && r[3] < 1);
        assert_true(r[0] >= last_in); /* into glass R grows with the angle ... */
        last_in = r[0];
        lines++;
    }
    assert_int_equal(STEPS + 1, lines);
    assert_close(1, last_in, 5e-7); /* ... to 1 at grazing incidence */
}

static const graded_test tests[] = {
    GRADED(test_fresnel_table, 0),
};

SUITE_MAIN("lab_09_refraction", tests)
