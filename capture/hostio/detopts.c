/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Detector options shared by the CLI and the capture app.
 */
#include "detopts.h"

#include "symline/binning.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* How an option's value is written; the config field keeps the library's unit. */
typedef enum opt_unit {
    UNIT_INT = 0,    /* an integer in [lo, hi], stored as it is (unsigned fields) */
    UNIT_SIGNED = 1, /* an integer in [lo, hi], possibly negative (signed fields) */
    UNIT_PX = 2,     /* pixels as a decimal ("2", "2.5"), stored in Q8; [lo, hi] in Q8 */
    UNIT_BOOL = 3    /* 0 or 1, a bool field */
} opt_unit;

/* A numeric option: name, unit, range and the config field it sets (symline/detect.h). */
typedef struct num_opt {
    const char *name;
    opt_unit unit;
    int64_t lo, hi;
    size_t offset;
} num_opt;

#define PX_MAX ((int64_t)SYMLINE_MAX_DIM << 8)

static const num_opt num_opts[] = {
    {"--radius", UNIT_INT, 1, SYMLINE_DETECT_MAX_RADIUS, offsetof(symline_config, radius)},
    {"--levels", UNIT_INT, 0, SYMLINE_DETECT_MAX_LEVELS, offsetof(symline_config, levels)},
    {"--illumination", UNIT_INT, 0, 255, offsetof(symline_config, illumination)},
    {"--adaptive", UNIT_BOOL, 0, 1, offsetof(symline_config, adaptive)},
    {"--bright-sigma", UNIT_SIGNED, -100, 100, offsetof(symline_config, bright_sigma10)},
    {"--side-sigma", UNIT_SIGNED, -100, 100, offsetof(symline_config, side_sigma10)},
    {"--ridge-sigma", UNIT_INT, 0, 100, offsetof(symline_config, ridge_sigma10)},
    {"--a-distance", UNIT_INT, 0, SYMLINE_DETECT_MAX_A_DISTANCE,
     offsetof(symline_config, a_distance)},
    {"--contrast", UNIT_INT, 0, 100, offsetof(symline_config, contrast_pct)},
    {"--contrast-min", UNIT_INT, 0, 255, offsetof(symline_config, contrast_min)},
    {"--contrast-asym", UNIT_INT, 0, 1000, offsetof(symline_config, contrast_asym_pct)},
    {"--min-length", UNIT_INT, 0, SYMLINE_MAX_DIM, offsetof(symline_config, min_length)},
    {"--curve-dev", UNIT_PX, 0, PX_MAX, offsetof(symline_config, curve_dev_q8)},
    {"--curve-bend", UNIT_PX, 0, PX_MAX, offsetof(symline_config, curve_bend_q8)},
    {"--merge-gap", UNIT_INT, 0, SYMLINE_MAX_DIM, offsetof(symline_config, merge_gap)},
    {"--merge-dev", UNIT_PX, 0, PX_MAX, offsetof(symline_config, merge_dev_q8)},
    {"--field-margin", UNIT_INT, 0, SYMLINE_MAX_DIM, offsetof(symline_config, field_margin)},
};
#define NUM_OPTS (sizeof num_opts / sizeof num_opts[0])

static int opt_index(const char *name)
{
    size_t i;
    for (i = 0; i < NUM_OPTS; i++) {
        if (strcmp(name, num_opts[i].name) == 0) {
            return (int)i;
        }
    }
    return -1;
}

int detopts_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out)
{
    char *end;
    unsigned long v;
    if (s == NULL || *s < '0' || *s > '9') {
        return -1;
    }
    errno = 0;
    v = strtoul(s, &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) {
        return -1;
    }
    *out = (uint32_t)v;
    return 0;
}

/* A signed decimal integer in [lo, hi], nothing else; 0 on success. */
static int parse_int(const char *s, int64_t lo, int64_t hi, int64_t *out)
{
    char *end;
    long long v;
    if (s == NULL || !((*s >= '0' && *s <= '9') || (*s == '-' && s[1] >= '0' && s[1] <= '9'))) {
        return -1;
    }
    errno = 0;
    v = strtoll(s, &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) {
        return -1;
    }
    *out = (int64_t)v;
    return 0;
}

/* Pixels as a decimal with up to 6 fraction digits, rounded to Q8 (1/256 px); no floating point. */
static int parse_px_q8(const char *s, int64_t lo, int64_t hi, int64_t *out)
{
    int64_t ip = 0, frac = 0, scale = 1, q;
    int digits = 0;
    if (s == NULL || *s < '0' || *s > '9') {
        return -1;
    }
    for (; *s >= '0' && *s <= '9'; s++) {
        ip = ip * 10 + (*s - '0');
        if (ip > SYMLINE_MAX_DIM) {
            return -1;
        }
    }
    if (*s == '.') {
        for (s++; *s >= '0' && *s <= '9'; s++) {
            if (++digits > 6) {
                return -1;
            }
            frac = frac * 10 + (*s - '0');
            scale *= 10;
        }
        if (digits == 0) {
            return -1;
        }
    }
    if (*s != '\0') {
        return -1;
    }
    q = ip * 256 + (frac * 256 + scale / 2) / scale;
    if (q < lo || q > hi) {
        return -1;
    }
    *out = q;
    return 0;
}

/* A Q8 value as pixels: "2", "2.5", "0.31" (two decimals at most, trailing zeros dropped). */
static void put_px(FILE *f, uint32_t q8)
{
    uint32_t h = (uint32_t)(((uint64_t)q8 * 100u + 128u) >> 8);
    if (h % 100u == 0u) {
        fprintf(f, "%u", h / 100u);
    } else if (h % 10u == 0u) {
        fprintf(f, "%u.%u", h / 100u, (h % 100u) / 10u);
    } else {
        fprintf(f, "%u.%02u", h / 100u, h % 100u);
    }
}

void detopts_init(detopts *d)
{
    symline_config_default(&d->cfg);
    d->seen = 0;
    d->bin = DETOPTS_BIN_AUTO;
}

int detopts_bins(detopts_bin bin, uint32_t width, uint32_t height)
{
    if (symline_bin2_size(width, height) == 0u) {
        return 0; /* a side below 2 px: nothing to bin */
    }
    return bin == DETOPTS_BIN_ON ||
           (bin == DETOPTS_BIN_AUTO && symline_bin2_advised(width, height));
}

int detopts_bin_parse(const char *value, detopts_bin *bin)
{
    if (value != NULL && strcmp(value, "auto") == 0) {
        *bin = DETOPTS_BIN_AUTO;
    } else if (value != NULL && strcmp(value, "off") == 0) {
        *bin = DETOPTS_BIN_OFF;
    } else if (value != NULL && strcmp(value, "on") == 0) {
        *bin = DETOPTS_BIN_ON;
    } else {
        return -1;
    }
    return 0;
}

/* One detector option by name ("--radius") and value; 1 done, 0 not one, -1 bad value. */
static int apply_named(detopts *d, const char *name, const char *value, char *err, size_t errlen)
{
    int k;
    if (strcmp(name, "--axis") == 0) {
        if (value != NULL && strcmp(value, "horizontal") == 0) {
            d->cfg.axes = SYMLINE_AXES_HORIZONTAL;
        } else if (value != NULL && strcmp(value, "vertical") == 0) {
            d->cfg.axes = SYMLINE_AXES_VERTICAL;
        } else if (value != NULL && strcmp(value, "both") == 0) {
            d->cfg.axes = SYMLINE_AXES_BOTH;
        } else {
            snprintf(err, errlen, "--axis needs horizontal, vertical or both");
            return -1;
        }
    } else if (strcmp(name, "--filter") == 0) {
        if (value != NULL && strcmp(value, "contrast") == 0) {
            d->cfg.filter = SYMLINE_FILTER_CONTRAST;
        } else if (value != NULL && strcmp(value, "paper") == 0) {
            d->cfg.filter = SYMLINE_FILTER_PAPER;
        } else {
            snprintf(err, errlen, "--filter needs contrast or paper");
            return -1;
        }
    } else if (strcmp(name, "--field") == 0) {
        if (value != NULL && strcmp(value, "drop") == 0) {
            d->cfg.field_boundary = SYMLINE_FIELD_DROP;
        } else if (value != NULL && strcmp(value, "keep") == 0) {
            d->cfg.field_boundary = SYMLINE_FIELD_KEEP;
        } else if (value != NULL && strcmp(value, "off") == 0) {
            d->cfg.field_boundary = SYMLINE_FIELD_OFF;
        } else {
            snprintf(err, errlen, "--field needs drop, keep or off");
            return -1;
        }
    } else if (strcmp(name, "--bin") == 0) {
        if (detopts_bin_parse(value, &d->bin) != 0) {
            snprintf(err, errlen, "--bin needs auto, off or on");
            return -1;
        }
    } else if ((k = opt_index(name)) >= 0) {
        const num_opt *o = &num_opts[k];
        char *field = (char *)&d->cfg + o->offset;
        int64_t v;
        if (strcmp(name, "--merge-gap") == 0 && value != NULL && strcmp(value, "auto") == 0) {
            v = 0xFFFFFFFF; /* the library's "width / 8" */
        } else if (o->unit == UNIT_PX ? parse_px_q8(value, o->lo, o->hi, &v) != 0
                                      : parse_int(value, o->lo, o->hi, &v) != 0) {
            if (o->unit == UNIT_PX) {
                snprintf(err, errlen, "%s needs pixels, a decimal 0..%u (e.g. 2.5)", name,
                         (unsigned)(o->hi >> 8));
            } else {
                snprintf(err, errlen, "%s needs an integer %lld..%lld%s", name, (long long)o->lo,
                         (long long)o->hi, strcmp(name, "--merge-gap") == 0 ? ", or auto" : "");
            }
            return -1;
        }
        if (o->unit == UNIT_BOOL) {
            const bool b = v != 0;
            memcpy(field, &b, sizeof b);
        } else if (o->unit == UNIT_SIGNED) {
            const int32_t sv = (int32_t)v;
            memcpy(field, &sv, sizeof sv);
        } else {
            const uint32_t uv = (uint32_t)v;
            memcpy(field, &uv, sizeof uv);
        }
        d->seen |= 1u << k;
    } else {
        return 0;
    }
    return 1;
}

/* The option names getopt_long sees, without "--": the word options, then the numeric table. */
static const char *const words[] = {"--axis", "--filter", "--field", "--bin"};
#define NUM_WORDS (sizeof words / sizeof words[0])

static const char *long_name(size_t k)
{
    return (k < NUM_WORDS ? words[k] : num_opts[k - NUM_WORDS].name) + 2;
}

size_t detopts_longopts(struct option *out, size_t cap)
{
    size_t k, n = 0;
    for (k = 0; k < NUM_WORDS + NUM_OPTS && n < cap; k++, n++) {
        out[n].name = long_name(k);
        out[n].has_arg = required_argument;
        out[n].flag = NULL;
        out[n].val = DETOPTS_VAL + (int)k;
    }
    return n;
}

int detopts_apply(detopts *d, int code, const char *arg, char *err, size_t errlen)
{
    char name[32];
    if (code < DETOPTS_VAL || code >= DETOPTS_VAL + (int)(NUM_WORDS + NUM_OPTS)) {
        return 0;
    }
    snprintf(name, sizeof name, "--%s", long_name((size_t)(code - DETOPTS_VAL)));
    return apply_named(d, name, arg, err, errlen) == 1 ? 1 : -1;
}

uint32_t detopts_point_cap(uint32_t width, uint32_t height)
{
    const uint64_t want = 2u * (uint64_t)width * height + 1024u;
    const uint64_t lim = 0xFFFFFFFFu / sizeof(symline_point);
    return want > lim ? (uint32_t)lim : (uint32_t)want;
}

void detopts_finish(detopts *d)
{
    /* The paper's baseline: a fixed illumination threshold of 100, nothing adaptive. */
    if (d->cfg.filter == SYMLINE_FILTER_PAPER) {
        if (!(d->seen & (1u << opt_index("--illumination")))) {
            d->cfg.illumination = 100u;
        }
        if (!(d->seen & (1u << opt_index("--adaptive")))) {
            d->cfg.adaptive = 0u;
        }
    }
}

void detopts_help(FILE *f)
{
    symline_config c;
    symline_config_default(&c);
    /* Units and ranges are the library's (symline/detect.h); sigma values in tenths. */
    fprintf(f,
            "  --axis horizontal|vertical|both   axes to run (default both)\n"
            "  --radius M          symmetry radius 1..32, the detector's range (symmetry and\n"
            "                      extrema alone take 1..255) (%u)\n"
            "  --levels L          scales 0..5: 1 = full resolution only, L = also 2x .. 2^(L-1)x\n"
            "                      downsampled, 0 = auto: enough for lines width/16 px wide (%u)\n"
            "  --filter contrast|paper   line filter (default contrast; 'paper' is the\n"
            "                      A1-S baseline and implies --illumination 100\n"
            "                      --adaptive 0)\n"
            "  --illumination G    minimum gray value of a line point, 0..255, 0 = off (%u)\n"
            "  --adaptive 0|1      thresholds follow the frame's mean and sigma (%u)\n"
            "  --bright-sigma B    adaptive: gray >= mean + B/10 sigma, -100..100 (%d)\n"
            "  --ridge-sigma R     adaptive: ridge height >= R/10 sigma, 0..100 (%u)\n"
            "  --side-sigma S      adaptive: both sides of a ridge <= mean + S/10 sigma,\n"
            "                      -100..100; 100 = off (%d)\n"
            "  --a-distance D      paper filter: A point within D px across the line, 0..32,\n"
            "                      0 = the radius (%u)\n"
            "  --contrast PCT      contrast filter: ridge height, %% of centre gray, 0..100 (%u)\n"
            "  --contrast-min G    contrast filter: ridge height in gray levels, 0..255 (%u)\n"
            "  --contrast-asym PCT contrast filter: ridge height >= PCT %% of |left - right|\n"
            "                      per point, and 2 x PCT %% of the sides' difference\n"
            "                      averaged along each piece (rejects bands between two\n"
            "                      different surfaces), 0..1000, 0 = off (%u)\n"
            "  --min-length PX     shortest reported piece, px (%u)\n",
            c.radius, c.levels, c.illumination, c.adaptive ? 1u : 0u, (int)c.bright_sigma10,
            c.ridge_sigma10, (int)c.side_sigma10, c.a_distance, c.contrast_pct, c.contrast_min,
            c.contrast_asym_pct, c.min_length);
    fputs("  --curve-dev PX      curve threshold on max_dev, px, e.g. 2.5 (", f);
    put_px(f, c.curve_dev_q8);
    fputs(")\n"
          "  --curve-bend PX     also a curve: middle half this far off the chord against\n"
          "                      the outer quarters, px at the pass's scale, 0 = off (",
          f);
    put_px(f, c.curve_bend_q8);
    fputs(")\n"
          "  --merge-gap PX|auto merge collinear lines up to PX apart, 0 = no merging\n"
          "                      (default auto: width/8)\n"
          "  --merge-dev PX      merge tolerance across the line, px (",
          f);
    put_px(f, c.merge_dev_q8);
    fputs(")\n", f);
    fprintf(f,
            "  --field drop|keep|off   field boundary (symline boundary): reported as\n"
            "                      field_boundary; drop: line points above it are not\n"
            "                      traced (default); keep: nothing dropped; off: not\n"
            "                      computed\n"
            "  --field-margin PX   drop keeps points up to PX above the boundary (%u)\n"
            "  --bin auto|off|on   detect at half size, each pixel the mean of a 2x2 block,\n"
            "                      coordinates reported in the frame's pixels; auto: frames\n"
            "                      of %u pixels (1024x768) or more (default). The options\n"
            "                      in px then count pixels of the half-size frame.\n",
            c.field_margin, SYMLINE_BIN2_ADVISED_PIXELS);
}
