/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scorer on hand-made ground truth and detections whose scores are known
 * exactly (docs/evaluation.md: samples every 0.5 px, tolerance max(2, 3*W/640)).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>

#include "evio.h"
#include "score.h"

static void seg(ev_paths *p, int tag, double x0, double y0, double x1, double y1)
{
    ev_paths_begin(p, tag);
    ev_paths_add(p, x0, y0);
    ev_paths_add(p, x1, y1);
}

static ev_score score_json(const ev_paths *gt, const ev_paths *dc, const char *json, double tol)
{
    ev_paths det;
    ev_score s;
    int w, h;
    ev_paths_init(&det);
    assert_int_equal(ev_parse_detections(json, "test", &det, &w, &h), 0);
    ev_score_paths(gt, dc, &det, tol, &s);
    ev_paths_free(&det);
    return s;
}

static void test_tolerance(void **state)
{
    (void)state;
    assert_true(ev_tolerance(320) == 2.0);
    assert_true(ev_tolerance(640) == 3.0);
    assert_true(ev_tolerance(1280) == 6.0);
}

static void test_sampling(void **state)
{
    ev_paths p;
    ev_pt *s;
    size_t n;
    (void)state;
    ev_paths_init(&p);
    seg(&p, EV_TAG_LINE, 10, 10, 110, 10);  /* 100 px: 201 samples */
    seg(&p, EV_TAG_LINE, 5, 5, 5, 5);       /* a point: 1 sample */
    seg(&p, EV_TAG_LINE, 0, 0, 0.3, 0.4);   /* 0.5 px: 2 samples */
    n = ev_sample(&p, 0.5, &s, NULL);
    assert_int_equal(n, 201 + 1 + 2);
    assert_true(s[200].x == 110.0 && s[1].x == 10.5);
    free(s);
    ev_paths_free(&p);
}

static void test_perfect(void **state)
{
    ev_paths gt;
    ev_score s;
    (void)state;
    ev_paths_init(&gt);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);
    s = score_json(&gt, NULL,
                   "{\"width\": 320, \"height\": 240, \"segments\": [{\"x0\": 10, \"y0\": 10, "
                   "\"x1\": 110, \"y1\": 10, \"kind\": \"line\"}]}",
                   2.0);
    assert_true(s.p == 1.0 && s.r == 1.0 && s.f1 == 1.0);
    assert_int_equal(s.gt_samples, 201);
    assert_int_equal(s.line_matched, 1);
    assert_int_equal(s.line_ok, 1);
    assert_int_equal(s.line_matched_s, 201);
    assert_int_equal(s.line_ok_s, 201);
    ev_paths_free(&gt);
}

static void test_shifted(void **state)
{
    ev_paths gt;
    ev_score s;
    (void)state;
    ev_paths_init(&gt);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);
    /* Within tolerance: still perfect. */
    s = score_json(&gt, NULL,
                   "{\"segments\":[{\"x0\":10,\"y0\":12,\"x1\":110,\"y1\":12,\"kind\":\"line\"}]}",
                   2.0);
    assert_true(s.f1 == 1.0);
    /* 3 px beyond the tolerance: nothing right, nothing found. */
    s = score_json(&gt, NULL,
                   "{\"segments\":[{\"x0\":10,\"y0\":15,\"x1\":110,\"y1\":15,\"kind\":\"line\"}]}",
                   2.0);
    assert_true(s.p == 0.0 && s.r == 0.0 && s.f1 == 0.0);
    assert_int_equal(s.line_matched, 0);
    ev_paths_free(&gt);
}

static void test_half_length(void **state)
{
    ev_paths gt;
    ev_score s;
    (void)state;
    ev_paths_init(&gt);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);
    /* Detection covers x 10..60; GT samples up to x = 62 are within 2 px: 105 of 201. */
    s = score_json(&gt, NULL,
                   "{\"segments\":[{\"x0\":10,\"y0\":10,\"x1\":60,\"y1\":10,\"kind\":\"line\"}]}",
                   2.0);
    assert_true(s.p == 1.0);
    assert_int_equal(s.gt_hits, 105);
    assert_true(s.r == 105.0 / 201.0);
    assert_true(s.f1 == 2.0 * (105.0 / 201.0) / (1.0 + 105.0 / 201.0));
    ev_paths_free(&gt);
}

static void test_dontcare(void **state)
{
    ev_paths gt, dc;
    ev_score s;
    (void)state;
    ev_paths_init(&gt);
    ev_paths_init(&dc);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);
    seg(&dc, EV_TAG_LINE, 10, 100, 110, 100);
    /* The second detection lies on a don't-care part: ignored, precision stays 1. */
    s = score_json(&gt, &dc,
                   "{\"segments\":[{\"x0\":10,\"y0\":10,\"x1\":110,\"y1\":10,\"kind\":\"line\"},"
                   "{\"x0\":10,\"y0\":101,\"x1\":110,\"y1\":101,\"kind\":\"line\"}]}",
                   2.0);
    assert_true(s.f1 == 1.0);
    assert_int_equal(s.det_samples, 402);
    assert_int_equal(s.det_counted, 201);
    /* Without the don't-care list the same detection halves the precision. */
    s = score_json(&gt, NULL,
                   "{\"segments\":[{\"x0\":10,\"y0\":10,\"x1\":110,\"y1\":10,\"kind\":\"line\"},"
                   "{\"x0\":10,\"y0\":101,\"x1\":110,\"y1\":101,\"kind\":\"line\"}]}",
                   2.0);
    assert_true(s.p == 0.5 && s.r == 1.0);
    ev_paths_free(&gt);
    ev_paths_free(&dc);
}

static void test_curve_polyline(void **state)
{
    ev_paths gt;
    ev_score s;
    (void)state;
    ev_paths_init(&gt);
    /* A right-angle "arc" from (0,50) via (50,0) to (100,50). */
    ev_paths_begin(&gt, EV_TAG_CURVE);
    ev_paths_add(&gt, 0, 50);
    ev_paths_add(&gt, 50, 0);
    ev_paths_add(&gt, 100, 50);
    s = score_json(&gt, NULL,
                   "{\"segments\":[{\"x0\":0,\"y0\":50,\"x1\":100,\"y1\":50,\"kind\":\"curve\","
                   "\"polyline\":[[0,50],[50,0],[100,50]]}]}",
                   2.0);
    assert_true(s.f1 == 1.0);
    assert_int_equal(s.curve_matched, 1);
    assert_int_equal(s.curve_ok, 1);
    /* Without a polyline the chord is scored: only its ends touch the arc. */
    s = score_json(&gt, NULL,
                   "{\"segments\":[{\"x0\":0,\"y0\":50,\"x1\":100,\"y1\":50,\"kind\":\"line\"}]}",
                   2.0);
    assert_true(s.p < 0.1 && s.r < 0.1);
    assert_int_equal(s.curve_matched, 0);
    /* Matched to the arc but called a line: a classification error. */
    s = score_json(&gt, NULL,
                   "{\"segments\":[{\"x0\":0,\"y0\":50,\"x1\":100,\"y1\":50,\"kind\":\"line\","
                   "\"polyline\":[[0,50],[50,0],[100,50]]}]}",
                   2.0);
    assert_int_equal(s.curve_matched, 1);
    assert_int_equal(s.curve_ok, 0);
    assert_true(s.curve_matched_s == s.det_samples && s.curve_ok_s == 0);
    ev_paths_free(&gt);
}

static void test_empty(void **state)
{
    ev_paths gt;
    ev_score s;
    (void)state;
    ev_paths_init(&gt);
    s = score_json(&gt, NULL, "{\"width\":320,\"height\":240,\"segments\":[]}", 2.0);
    assert_true(s.f1 == 1.0);
    s = score_json(&gt, NULL, "{\"segments\":[{\"x0\":1,\"y0\":1,\"x1\":9,\"y1\":1}]}", 2.0);
    assert_true(s.p == 0.0 && s.r == 1.0 && s.f1 == 0.0);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);
    s = score_json(&gt, NULL, "{\"segments\":[]}", 2.0);
    assert_true(s.p == 1.0 && s.r == 0.0 && s.f1 == 0.0);
    ev_paths_free(&gt);
}

static void test_json(void **state)
{
    ev_paths det;
    int w, h;
    (void)state;
    ev_paths_init(&det);
    assert_int_equal(ev_parse_detections(
                         " {\n \"width\" : 640 , \"version\": {\"a\": [1, 2, {\"b\": null}]},"
                         " \"height\":480, \"segments\" : [ {\"axis\":\"horizontal\", \"x0\":1.5e1,"
                         " \"y0\":-2, \"x1\":3, \"y1\":4, \"points\": 7, \"max_dev\": 0.25,"
                         " \"kind\":\"curve\", \"ok\": true, \"s\": \"a\\\"b\"} ] } \n",
                         "t", &det, &w, &h),
                     0);
    assert_int_equal(w, 640);
    assert_int_equal(h, 480);
    assert_int_equal(det.npieces, 1);
    assert_int_equal(det.tag[0], EV_TAG_CURVE);
    assert_true(det.pts[0].x == 15.0 && det.pts[0].y == -2.0 && det.pts[1].y == 4.0);
    ev_paths_free(&det);
    ev_paths_init(&det);
    assert_int_equal(ev_parse_detections("{\"segments\":[{\"x0\":1,\"y0\":2,\"x1\":3}]}", "t",
                                         &det, &w, &h),
                     -1);
    assert_int_equal(ev_parse_detections("{\"segments\":[", "t", &det, &w, &h), -1);
    assert_int_equal(ev_parse_detections("{\"segments\":[]} x", "t", &det, &w, &h), -1);
    assert_int_equal(ev_parse_detections("[]", "t", &det, &w, &h), -1);
    ev_paths_free(&det);
}

static void test_mask(void **state)
{
    unsigned char mask[40 * 30] = {0};
    ev_paths det;
    ev_score s;
    int x, w, h;
    (void)state;
    for (x = 5; x <= 34; x++) {
        mask[15 * 40 + x] = 255;
    }
    ev_paths_init(&det);
    assert_int_equal(ev_parse_detections("{\"segments\":[{\"x0\":5,\"y0\":15,\"x1\":34,\"y1\":15}]}",
                                         "t", &det, &w, &h),
                     0);
    ev_score_mask(mask, 40, 30, &det, 2.0, &s);
    assert_true(s.f1 == 1.0);
    assert_int_equal(s.gt_samples, 30);
    ev_paths_free(&det);
    ev_paths_init(&det);
    assert_int_equal(ev_parse_detections("{\"segments\":[{\"x0\":5,\"y0\":20,\"x1\":34,\"y1\":20}]}",
                                         "t", &det, &w, &h),
                     0);
    ev_score_mask(mask, 40, 30, &det, 2.0, &s);
    assert_true(s.f1 == 0.0);
    ev_paths_free(&det);
}

static void test_ignore(void **state)
{
    /* Pixels with x >= 60 are ignored: the detection covers x 10..60 of a GT 10..110. */
    static unsigned char ign[120 * 20];
    ev_labels ignore;
    ev_paths gt, det;
    ev_score s;
    ev_extras ex = {NULL, NULL, NULL, NULL, NULL};
    int x, y, w, h;
    (void)state;
    for (y = 0; y < 20; y++) {
        for (x = 60; x < 120; x++) {
            ign[y * 120 + x] = 255;
        }
    }
    ignore.px = ign;
    ignore.width = 120;
    ignore.height = 20;
    ev_paths_init(&gt);
    ev_paths_init(&det);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);
    assert_int_equal(ev_parse_detections("{\"segments\":[{\"x0\":10,\"y0\":10,\"x1\":60,\"y1\":10}]}",
                                         "t", &det, &w, &h),
                     0);
    ex.ignore = &ignore;
    ev_score_paths_ex(&gt, NULL, &det, 2.0, &s, &ex);
    /* Samples at x < 59.5 remain (x = 59.5 rounds to pixel 60): 99 of each, all matched. */
    assert_int_equal(s.gt_samples, 99);
    assert_int_equal(s.det_counted, 99);
    assert_true(s.f1 == 1.0);
    ev_paths_free(&gt);
    ev_paths_free(&det);
}

/* The grid index answers exactly like a scan over every segment. */
static void test_index_exact(void **state)
{
    ev_paths p;
    ev_index ix;
    unsigned long r = 12345;
    int round, k, q, hits = 0;
    (void)state;
    for (round = 0; round < 20; round++) {
        double tol = 1.0 + round * 0.4;
        ev_paths_init(&p);
        for (k = 0; k < 30; k++) {
            int npts = 1 + (int)((r = r * 1103515245ul + 12345ul) >> 16) % 4, j;
            ev_paths_begin(&p, k % 2);
            for (j = 0; j < npts; j++) {
                double x = (double)((r = r * 1103515245ul + 12345ul) >> 16 & 1023) / 2.0 - 100.0;
                double y = (double)((r = r * 1103515245ul + 12345ul) >> 16 & 1023) / 3.0 - 50.0;
                ev_paths_add(&p, x, y);
            }
        }
        ev_index_build(&ix, &p, tol);
        for (q = 0; q < 3000; q++) {
            ev_pt pt;
            size_t i, j;
            int brute = 0;
            pt.x = (double)((r = r * 1103515245ul + 12345ul) >> 16 & 4095) / 6.0 - 150.0;
            pt.y = (double)((r = r * 1103515245ul + 12345ul) >> 16 & 4095) / 8.0 - 100.0;
            for (i = 0; i < p.npieces && !brute; i++) {
                const ev_pt *a = ev_piece_pts(&p, i);
                size_t n = ev_piece_len(&p, i);
                if (n == 1) {
                    brute = ev_dist_point_seg(pt, a[0], a[0]) <= tol;
                }
                for (j = 0; j + 1 < n && !brute; j++) {
                    brute = ev_dist_point_seg(pt, a[j], a[j + 1]) <= tol;
                }
            }
            assert_int_equal(ev_index_near(&ix, pt, NULL), brute);
            {
                /* The nearest distance, exactly as the scan over every segment finds it. */
                double best = -1.0, d = ev_index_dist(&ix, pt);
                for (i = 0; i < p.npieces; i++) {
                    double e = ev_dist_piece(&p, i, pt); /* -1: a piece without points */
                    if (e >= 0.0 && e <= tol && (best < 0.0 || e < best)) {
                        best = e;
                    }
                }
                assert_true(d == best);
            }
            hits += brute;
        }
        ev_index_free(&ix);
        ev_paths_free(&p);
    }
    printf("index: %d of 60000 queries near a segment\n", hits);
    assert_true(hits > 3000 && hits < 57000); /* both answers well exercised */
}

static void test_labels(void **state)
{
    /* 40x30 label image: paint (1) on rows 13..17 (5 px wide) from x 5 to 34, a wall (3) row 2. */
    unsigned char lab[40 * 30] = {0};
    ev_labels labels;
    ev_paths gt, det;
    ev_score s;
    int x, y, w, h;
    (void)state;
    for (y = 13; y <= 17; y++) {
        for (x = 5; x <= 34; x++) {
            lab[y * 40 + x] = 1;
        }
    }
    for (x = 0; x < 40; x++) {
        lab[2 * 40 + x] = 3;
    }
    labels.px = lab;
    labels.width = 40;
    labels.height = 30;
    ev_paths_init(&gt);
    ev_paths_init(&det);
    seg(&gt, EV_TAG_LINE, 10, 15, 30, 15); /* 41 samples */
    assert_int_equal(ev_parse_detections("{\"segments\":[{\"x0\":10,\"y0\":15,\"x1\":20,\"y1\":15},"
                                         "{\"x0\":0,\"y0\":2,\"x1\":9,\"y1\":2}]}",
                                         "t", &det, &w, &h),
                     0);
    {
        ev_extras ex = {NULL, NULL, NULL, NULL, NULL};
        ex.labels = &labels;
        ev_score_paths_ex(&gt, NULL, &det, 2.0, &s, &ex);
    }
    /* Wrong samples: the 19 on the wall row. */
    assert_int_equal(s.fp_label[3], 19);
    assert_int_equal(s.fp_label[0] + s.fp_label[1], 0);
    /* All 41 ground-truth samples are 5 px wide (bucket 4-8); x 10..22 are found. */
    assert_int_equal(s.gt_width_n[2], 41);
    assert_int_equal(s.gt_width_hits[2], 25);
    ev_paths_free(&gt);
    ev_paths_free(&det);
}

/* Scores a detection JSON with extras (centre dump) against gt. */
static ev_score score_json_ex(const ev_paths *gt, const ev_paths *dc, const char *json,
                              FILE *centre)
{
    ev_paths det;
    ev_score s;
    ev_extras ex;
    int w, h;
    memset(&ex, 0, sizeof(ex));
    ex.centre = centre;
    ev_paths_init(&det);
    assert_int_equal(ev_parse_detections(json, "test", &det, &w, &h), 0);
    ev_score_paths_ex(gt, dc, &det, 2.0, &s, &ex);
    ev_paths_free(&det);
    return s;
}

/* Three pieces along one long line count 3; a crossing piece, a 3-sample piece and
   pieces along short or circle ground truth do not count; a line nothing lies along
   is not found. */
static void test_fragmentation(void **state)
{
    ev_paths gt;
    ev_score s;
    (void)state;
    ev_paths_init(&gt);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);  /* 100 px: counts */
    seg(&gt, EV_TAG_LINE, 10, 50, 30, 50);   /* 20 px: too short */
    seg(&gt, EV_TAG_CURVE, 10, 80, 110, 80); /* circle ground truth: not straight */
    seg(&gt, EV_TAG_LINE, 200, 10, 200, 60); /* 50 px: counts, nothing along it */
    s = score_json_ex(&gt, NULL,
                      "{\"segments\":[{\"x0\":10,\"y0\":10,\"x1\":40,\"y1\":10},"
                      "{\"x0\":45,\"y0\":11,\"x1\":75,\"y1\":11},"
                      "{\"x0\":80,\"y0\":9,\"x1\":110,\"y1\":9},"
                      "{\"x0\":60,\"y0\":0,\"x1\":60,\"y1\":30},"
                      "{\"x0\":50,\"y0\":10,\"x1\":51,\"y1\":10},"
                      "{\"x0\":10,\"y0\":50,\"x1\":30,\"y1\":50},"
                      "{\"x0\":10,\"y0\":80,\"x1\":110,\"y1\":80}]}",
                      NULL);
    assert_int_equal(s.frag_pieces, 2);
    assert_int_equal(s.frag_found, 1);
    assert_int_equal(s.frag_segments, 3);
    /* One piece from x 0 to 130 along the first line: the samples at x 8..112 are within
       2 px of it, 209 of 261 = 80 %: one piece, fragmentation 1. */
    s = score_json_ex(&gt, NULL, "{\"segments\":[{\"x0\":0,\"y0\":10,\"x1\":130,\"y1\":10}]}",
                      NULL);
    assert_int_equal(s.frag_found, 1);
    assert_int_equal(s.frag_segments, 1);
    ev_paths_free(&gt);
}

/* The 70 % share and the 8-sample minimum at their limits. */
static void test_fragmentation_limits(void **state)
{
    ev_paths gt;
    ev_score s;
    (void)state;
    ev_paths_init(&gt);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);
    /* x 5..14.5: 20 samples, x >= 8 within 2 px: 14 = 70 %. */
    s = score_json_ex(&gt, NULL, "{\"segments\":[{\"x0\":5,\"y0\":10,\"x1\":14.5,\"y1\":10}]}",
                      NULL);
    assert_int_equal(s.frag_segments, 1);
    /* x 4.5..14: 13 of 20 = 65 %. */
    s = score_json_ex(&gt, NULL, "{\"segments\":[{\"x0\":4.5,\"y0\":10,\"x1\":14,\"y1\":10}]}",
                      NULL);
    assert_int_equal(s.frag_segments, 0);
    assert_int_equal(s.frag_found, 0);
    assert_int_equal(s.frag_pieces, 1);
    /* 8 samples (3.5 px) count, 7 (3 px) do not. */
    s = score_json_ex(&gt, NULL, "{\"segments\":[{\"x0\":50,\"y0\":10,\"x1\":53.5,\"y1\":10}]}",
                      NULL);
    assert_int_equal(s.frag_segments, 1);
    s = score_json_ex(&gt, NULL, "{\"segments\":[{\"x0\":50,\"y0\":10,\"x1\":53,\"y1\":10}]}",
                      NULL);
    assert_int_equal(s.frag_segments, 0);
    /* No detection: nothing found, nothing counted. */
    s = score_json_ex(&gt, NULL, "{\"segments\":[]}", NULL);
    assert_int_equal(s.frag_pieces, 1);
    assert_int_equal(s.frag_found + s.frag_segments, 0);
    ev_paths_free(&gt);
}

/* A detection tilted by 1 px over 100 px: 202 samples (length just over 100 px),
   sample k is k/201 px off the ground truth; an unmatched piece and samples near a
   don't-care part are left out. */
static void test_centre_error(void **state)
{
    ev_paths gt, dc;
    ev_score s;
    FILE *f = tmpfile();
    double d, sum = 0.0;
    int n = 0;
    (void)state;
    assert_non_null(f);
    ev_paths_init(&gt);
    ev_paths_init(&dc);
    seg(&gt, EV_TAG_LINE, 10, 10, 110, 10);
    s = score_json_ex(&gt, NULL, "{\"segments\":[{\"x0\":10,\"y0\":10.3,\"x1\":110,\"y1\":10.3}]}",
                      NULL);
    assert_int_equal(s.centre_n, 201);
    assert_true(fabs(s.centre_median - 0.3) < 1e-9 && fabs(s.centre_p90 - 0.3) < 1e-9);
    s = score_json_ex(&gt, NULL,
                      "{\"segments\":[{\"x0\":10,\"y0\":10,\"x1\":110,\"y1\":11},"
                      "{\"x0\":10,\"y0\":40,\"x1\":110,\"y1\":40}]}",
                      f);
    /* Nearest rank: median = value 101 of 202 (k = 100), p90 = value 182 (k = 181). */
    assert_int_equal(s.centre_n, 202);
    assert_true(fabs(s.centre_median - 100.0 / 201.0) < 1e-9);
    assert_true(fabs(s.centre_p90 - 181.0 / 201.0) < 1e-9);
    /* The dump holds the same 202 distances. */
    rewind(f);
    while (fscanf(f, "%lf", &d) == 1) {
        sum += d;
        n++;
    }
    assert_int_equal(n, 202);
    assert_true(fabs(sum - 101.0) < 0.01); /* sum of k/201 for k = 0..201 */
    /* Don't-care from x 10 to 30: samples with x <= 32 are left out, k = 45..201 remain
       (157); median = value 79 (k = 123), p90 = value 142 (k = 186). */
    seg(&dc, EV_TAG_OTHER, 10, 10, 30, 10);
    s = score_json_ex(&gt, &dc, "{\"segments\":[{\"x0\":10,\"y0\":10,\"x1\":110,\"y1\":11}]}",
                      NULL);
    assert_int_equal(s.centre_n, 157);
    assert_true(fabs(s.centre_median - 123.0 / 201.0) < 1e-9);
    assert_true(fabs(s.centre_p90 - 186.0 / 201.0) < 1e-9);
    /* Nothing matched: no centre error. */
    s = score_json_ex(&gt, NULL, "{\"segments\":[{\"x0\":10,\"y0\":40,\"x1\":110,\"y1\":40}]}",
                      NULL);
    assert_int_equal(s.centre_n, 0);
    fclose(f);
    ev_paths_free(&gt);
    ev_paths_free(&dc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tolerance),   cmocka_unit_test(test_sampling),
        cmocka_unit_test(test_perfect),     cmocka_unit_test(test_shifted),
        cmocka_unit_test(test_half_length), cmocka_unit_test(test_dontcare),
        cmocka_unit_test(test_curve_polyline), cmocka_unit_test(test_empty),
        cmocka_unit_test(test_json),        cmocka_unit_test(test_mask),
        cmocka_unit_test(test_labels),      cmocka_unit_test(test_index_exact),
        cmocka_unit_test(test_ignore),      cmocka_unit_test(test_fragmentation),
        cmocka_unit_test(test_fragmentation_limits), cmocka_unit_test(test_centre_error),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
