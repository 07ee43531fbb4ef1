/* lab_08_mirrors.c - chapter 08's lab: does a convex mirror see itself? (not graded)
 *
 * The lab's README states, from 20 000 rays a band: with the error-bound
 * policy no mirror ray sees the mirror again below theta_i = 89.9 degrees,
 * in either build, at any scale from 1e-4 to 1e8; started at the computed
 * point (none) about half of them do (27 % to 64 % a band).  Checked here
 * with 2 000 rays a band, at every scale of the table.
 */
#include "suite.h"

#include "08_mirrors/lab/self_hit.h"

static void test_bound_never_below_grazing(void **state)
{
    (void)state;
    for (int k = 0; k < SELF_HIT_SCALES; k++) {
        self_hit_result result;
        self_hit_measure(self_hit_scales[k], EPS_BOUND, 2000, &result);
        for (int b = 0; b < SELF_HIT_BANDS && self_hit_band_start[b + 1] <= 89.9; b++) {
            /* every eye ray meets the sphere this far from its rim (nearer it, a
             * rounded eye ray may pass it by: half of them in float beyond 89.99) */
            assert_int_equal(2000, result.rays[b]);
            if (result.hits[b] != 0)
                fail_msg("scale %g, theta_i from %g: %ld of %ld mirror rays saw the mirror with --shadow-eps=bound",
                         (double)self_hit_scales[k], self_hit_band_start[b], result.hits[b], result.rays[b]);
        }
    }
}

/* The blunder: a sizeable share of self-hits in every band at every scale
 * (a quarter of them or more in the table; at least a tenth here). */
static void test_none_sees_itself(void **state)
{
    (void)state;
    for (int k = 0; k < SELF_HIT_SCALES; k++) {
        self_hit_result result;
        self_hit_measure(self_hit_scales[k], EPS_NONE, 2000, &result);
        for (int b = 0; b < SELF_HIT_BANDS; b++)
            if (10 * result.hits[b] < result.rays[b])
                fail_msg("scale %g, theta_i from %g: only %ld of %ld mirror rays saw the mirror with --shadow-eps=none",
                         (double)self_hit_scales[k], self_hit_band_start[b], result.hits[b], result.rays[b]);
    }
}

static const graded_test tests[] = {
    GRADED(test_bound_never_below_grazing, 0),
    GRADED(test_none_sees_itself, 0),
};

SUITE_MAIN("lab_08_mirrors", tests)
