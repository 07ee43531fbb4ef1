/* main.c - chapter 09's lab: R against the angle, and where the precision gives out.
 *
 *     lab --fresnel-table   R against the angle (fresnel_table.h) for eta = 1.5,
 *                           both ways, for the plot of the README (fresnel.gp);
 *     lab --limits          where the build's precision gives out (glass_limits.h).
 */
#include <stdio.h>

#include "09_refraction/lab/fresnel_table.h"
#include "09_refraction/lab/glass_limits.h"
#include "lab_tables.h"

/* Eighth-degree steps from 0 to 90 degrees. */
static int fresnel_eta_1_5(void) { return fresnel_table(stdout, (real)1.5, 90 * 8); }

static int limits(void)
{
    glass_limits(stdout);
    return 0;
}

int main(int argc, char **argv)
{
    static const lab_table tables[] = {
        {"--fresnel-table", "R against the angle for eta 1.5, into and out of glass, exact and Schlick",
         fresnel_eta_1_5},
        {"--limits", "where the build's precision gives out in refraction", limits},
    };
    return lab_tables_main("09_refraction lab: Fresnel's R against the angle, and the limits of precision", tables,
                           2, argc, argv, stdout, stderr);
}
