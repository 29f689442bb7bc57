/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The integration test's JSON checker must reject what is not well formed.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "json_check.h"

#define GOOD_HEAD "{\"frame\": 3, \"sequence\": 7, \"timestamp_ns\": 123, \"latency_ms\": 1.5e0, \"stages_ms\": {\"detect\": 0.25}, "

static void test_values(void **state)
{
    (void)state;
    assert_null(json_check_value("{}"));
    assert_null(json_check_value(" [1, -0.5, 2e-3, \"a\\u00e9\\n\", true, false, null, {\"k\": []}] "));
    assert_non_null(json_check_value("{"));
    assert_non_null(json_check_value("[1,]"));
    assert_non_null(json_check_value("{\"a\" 1}"));
    assert_non_null(json_check_value("{\"a\": 01}"));
    assert_non_null(json_check_value("{\"a\": .5}"));
    assert_non_null(json_check_value("{\"a\": nan}"));
    assert_non_null(json_check_value("\"tab\there\""));
    assert_non_null(json_check_value("\"bad \\x escape\""));
    assert_non_null(json_check_value("{} {}"));
    assert_non_null(json_check_value("[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]"));
}

static void test_frame_lines(void **state)
{
    json_frame_info info;
    (void)state;
    assert_null(json_check_frame_line(GOOD_HEAD "\"segments\": []}\n", &info));
    assert_int_equal(info.frame, 3);
    assert_int_equal(info.sequence, 7);
    assert_int_equal(info.segments, 0);
    assert_null(json_check_frame_line(GOOD_HEAD "\"segments\": [{\"x0\": 1, \"y0\": 2.5, \"x1\": 3, \"y1\": 4, "
                                                "\"kind\": \"line\"}, {\"x0\": 0, \"y0\": 0, \"x1\": 9, \"y1\": 9}]}",
                                      &info));
    assert_int_equal(info.segments, 2);
    assert_non_null(json_check_frame_line(GOOD_HEAD "\"segments\": [{\"x0\": 1, \"y0\": 2}]}", &info));
    assert_non_null(json_check_frame_line(GOOD_HEAD "\"segments\": {}}", &info));
    assert_non_null(json_check_frame_line(GOOD_HEAD "\"segs\": []}", &info));
    assert_non_null(json_check_frame_line("{\"frame\": 1, \"segments\": []}", &info));
    assert_non_null(json_check_frame_line("[1, 2]", &info));
    assert_non_null(json_check_frame_line(GOOD_HEAD "\"segments\": [}", &info));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_frame_lines),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
