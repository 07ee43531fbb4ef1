/* main.c - chapter 08's lab: does a convex mirror see itself?  Measured.
 *
 *     lab --self-hit-table
 *
 * prints the self-hit measurement of a convex mirror (self_hit.h) for every
 * policy, scale and band of angles of incidence, for this build, one line
 * each: "build policy scale theta_i_from rays hits".
 */
#include <stdio.h>

#include "08_mirrors/lab/self_hit.h"
#include "lab_tables.h"

static int self_hit_table(void)
{
    printf("# build policy scale theta_i_from rays hits (a convex mirror seeing itself, self_hit.h)\n");
    for (int p = 0; eps_policy_names[p]; p++)
        for (int k = 0; k < SELF_HIT_SCALES; k++) {
            self_hit_result result;
            self_hit_measure(self_hit_scales[k], (eps_policy)p, 20000, &result);
            for (int b = 0; b < SELF_HIT_BANDS; b++)
                printf("%s %s %g %g %ld %ld\n", REAL_NAME, eps_policy_names[p], (double)self_hit_scales[k],
                       self_hit_band_start[b], result.rays[b], result.hits[b]);
        }
    return 0;
}

int main(int argc, char **argv)
{
    static const lab_table tables[] = {
        {"--self-hit-table", "how often a convex mirror sees itself, by policy, scale and angle", self_hit_table},
    };
    return lab_tables_main("08_mirrors lab: does a convex mirror see itself?", tables, 1, argc, argv, stdout,
                           stderr);
}
