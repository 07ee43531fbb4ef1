/* main.c - chapter 06's lab: shadow acne and light leaks, measured.
 *
 *     lab --acne-table
 *
 * prints the acne and leak measurement (acne.h) of every policy on both
 * shapes at every scale, for this build, one line each:
 * "build policy shape scale acne% leak%" (acne-leak.gp plots it, and the
 * bench's hook tabulates it).
 */
#include <stdio.h>

#include "06_shadows/lab/acne.h"
#include "lab_tables.h"

static int acne_table(void)
{
    for (int p = 0; eps_policy_names[p]; p++) {
        for (int shape = 0; shape < ACNE_SHAPES; shape++) {
            for (int k = 0; k < ACNE_SCALES; k++) {
                acne_result result;
                if (acne_measure((acne_shape)shape, acne_scales[k], (eps_policy)p, 64, &result) != 0) {
                    fprintf(stderr, "06_shadows lab: out of memory\n");
                    return 1;
                }
                printf("%s %s %s %g %.2f %.2f\n", REAL_NAME, eps_policy_names[p], acne_shape_names[shape],
                       (double)acne_scales[k], result.acne, result.leak);
            }
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    static const lab_table tables[] = {
        {"--acne-table", "acne and leaks of every --shadow-eps policy, shape and scale", acne_table},
    };
    return lab_tables_main("06_shadows lab: shadow acne and light leaks, measured", tables, 1, argc, argv, stdout,
                           stderr);
}
