/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The detector options of the host programs take the library's units and
 * ranges (symline/detect.h): sigma in signed tenths, lengths in pixels
 * (stored in Q8), 0 = auto where the library says so.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "detopts.h"

/* Parses argv (argv[0] is a name) with getopt_long; 0, or -1 on the first bad value. */
static int parse(detopts *d, int argc, char **argv)
{
    struct option longopts[64];
    char err[128];
    int c;
    size_t n = detopts_longopts(longopts, 63);
    memset(&longopts[n], 0, sizeof longopts[n]);
    detopts_init(d);
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":", longopts, NULL)) != -1) {
        if (detopts_apply(d, c, optarg, err, sizeof err) != 1) {
            return -1;
        }
    }
    detopts_finish(d);
    return 0;
}

static void test_library_units(void **state)
{
    char *argv[] = {"x",
                    "--side-sigma",
                    "15",
                    "--bright-sigma=-20",
                    "--ridge-sigma",
                    "9",
                    "--levels",
                    "0",
                    "--a-distance",
                    "0",
                    "--curve-dev",
                    "2.5",
                    "--curve-bend",
                    "0.3125",
                    "--merge-dev",
                    "2",
                    "--merge-gap",
                    "auto",
                    "--radius=32",
                    "--adaptive",
                    "0"};
    detopts d;
    (void)state;
    assert_int_equal(parse(&d, (int)(sizeof argv / sizeof argv[0]), argv), 0);
    assert_int_equal(d.cfg.side_sigma10, 15);
    assert_int_equal(d.cfg.bright_sigma10, -20);
    assert_int_equal(d.cfg.ridge_sigma10, 9);
    assert_int_equal(d.cfg.levels, 0);
    assert_int_equal(d.cfg.a_distance, 0);
    assert_int_equal(d.cfg.curve_dev_q8, 640);
    assert_int_equal(d.cfg.curve_bend_q8, 80);
    assert_int_equal(d.cfg.merge_dev_q8, 512);
    assert_int_equal(d.cfg.merge_gap, SYMLINE_MERGE_GAP_AUTO);
    assert_int_equal(d.cfg.radius, 32);
    assert_false(d.cfg.adaptive);
}

static void test_out_of_range(void **state)
{
    static char *bad[][3] = {{"x", "--side-sigma", "101"}, {"x", "--bright-sigma", "-101"},
                             {"x", "--radius", "33"},      {"x", "--radius", "0"},
                             {"x", "--levels", "6"},       {"x", "--curve-dev", "2.5x"},
                             {"x", "--curve-dev", "-1"},   {"x", "--merge-gap", "autox"},
                             {"x", "--curve-dev", ".5"},   {"x", "--curve-dev", "1.0000001"}};
    size_t i;
    detopts d;
    (void)state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(parse(&d, 3, bad[i]), -1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_library_units),
        cmocka_unit_test(test_out_of_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
