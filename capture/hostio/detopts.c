/*
 * Detector options shared by the CLI and the capture app.
 */
#include "detopts.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* A numeric option: name, range and the config field it sets. */
typedef struct num_opt {
    const char *name;
    uint32_t lo, hi;
    size_t offset;
    int32_t bias; /* signed fields are given as value + bias, so 0..200 stands for -100..100 */
    bool flag;    /* a bool field, given as 0 or 1 */
} num_opt;

static const num_opt num_opts[] = {
    {"--radius", 1, SYMLINE_DETECT_MAX_RADIUS, offsetof(symline_config, radius), 0, false},
    {"--levels", 1, SYMLINE_DETECT_MAX_LEVELS, offsetof(symline_config, levels), 0, false},
    {"--illumination", 0, 255, offsetof(symline_config, illumination), 0, false},
    {"--adaptive", 0, 1, offsetof(symline_config, adaptive), 0, true},
    {"--bright-sigma", 0, 200, offsetof(symline_config, bright_sigma10), 100, false},
    {"--side-sigma", 0, 200, offsetof(symline_config, side_sigma10), 100, false},
    {"--ridge-sigma", 0, 100, offsetof(symline_config, ridge_sigma10), 0, false},
    {"--a-distance", 1, SYMLINE_DETECT_MAX_A_DISTANCE, offsetof(symline_config, a_distance), 0,
     false},
    {"--contrast", 0, 100, offsetof(symline_config, contrast_pct), 0, false},
    {"--contrast-min", 0, 255, offsetof(symline_config, contrast_min), 0, false},
    {"--contrast-asym", 0, 1000, offsetof(symline_config, contrast_asym_pct), 0, false},
    {"--min-length", 0, 65535, offsetof(symline_config, min_length), 0, false},
    {"--curve-dev", 0, 65535u << 8, offsetof(symline_config, curve_dev_q8), 0, false},
    {"--curve-bend", 0, 65535u << 8, offsetof(symline_config, curve_bend_q8), 0, false},
    {"--merge-gap", 0, 65535, offsetof(symline_config, merge_gap), 0, false},
    {"--merge-dev", 0, 65535u << 8, offsetof(symline_config, merge_dev_q8), 0, false},
    {"--field-margin", 0, 65535, offsetof(symline_config, field_margin), 0, false},
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

void detopts_init(detopts *d)
{
    symline_config_default(&d->cfg);
    d->seen = 0;
}

int detopts_parse(detopts *d, int argc, char **argv, int *i, char *err, size_t errlen)
{
    const char *name = argv[*i];
    const char *value = (*i + 1 < argc) ? argv[*i + 1] : NULL;
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
    } else if ((k = opt_index(name)) >= 0) {
        const num_opt *o = &num_opts[k];
        char *field = (char *)&d->cfg + o->offset;
        uint32_t v;
        if (detopts_u32(value, o->lo, o->hi, &v) != 0) {
            snprintf(err, errlen, "%s needs an integer %u..%u", name, o->lo, o->hi);
            return -1;
        }
        if (o->flag) {
            const bool b = v != 0u;
            memcpy(field, &b, sizeof b);
        } else if (o->bias != 0) {
            const int32_t sv = (int32_t)v - o->bias;
            memcpy(field, &sv, sizeof sv);
        } else {
            memcpy(field, &v, sizeof v);
        }
        d->seen |= 1u << k;
    } else {
        return 0;
    }
    (*i)++;
    return 1;
}

void detopts_finish(detopts *d)
{
    /* The paper's baseline: a fixed illumination threshold of 100, nothing adaptive. */
    if (d->cfg.filter == SYMLINE_FILTER_PAPER) {
        if (!(d->seen & (1u << opt_index("--illumination")))) {
            d->cfg.illumination = 100u;
        }
        if (!(d->seen & (1u << opt_index("--adaptive")))) {
            d->cfg.adaptive = false;
        }
    }
}

void detopts_help(FILE *f)
{
    symline_config c;
    symline_config_default(&c);
    fprintf(f,
            "  --axis horizontal|vertical|both   axes to run (default both)\n"
            "  --radius M          symmetry radius 1..32 (%u)\n"
            "  --levels L          scales 1..5 (1 = full resolution only; default auto:\n"
            "                      enough 2x steps for lines width/16 px wide)\n"
            "  --filter contrast|paper   line filter (default contrast; 'paper' is the\n"
            "                      A1-S baseline and implies --illumination 100\n"
            "                      --adaptive 0)\n"
            "  --illumination G    minimum gray value of a line point, 0..255, 0 = off (%u)\n"
            "  --adaptive 0|1      thresholds follow the frame's mean and sigma (%u)\n"
            "  --bright-sigma B    adaptive: gray >= mean + (B-100)/10 sigma, 0..200 (%d)\n"
            "  --ridge-sigma R     adaptive: ridge height >= R/10 sigma, 0..100 (%u)\n"
            "  --side-sigma S      adaptive: both sides of a ridge <= mean + (S-100)/10\n"
            "                      sigma, 0..200; 200 = off (%d)\n"
            "  --a-distance D      paper filter: A point within D px across the line\n"
            "                      (default: the radius)\n"
            "  --contrast PCT      contrast filter: ridge height, %% of centre gray (%u)\n"
            "  --contrast-min G    contrast filter: ridge height in gray levels (%u)\n"
            "  --contrast-asym PCT contrast filter: ridge height >= PCT %% of |left - right|\n"
            "                      per point, and 2 x PCT %% of the sides' difference\n"
            "                      averaged along each piece (rejects bands between two\n"
            "                      different surfaces; 0 = off; %u)\n"
            "  --min-length PX     shortest reported piece (%u)\n"
            "  --curve-dev Q8      curve threshold on max_dev, 1/256 px (%u)\n"
            "  --curve-bend Q8     also a curve: middle half this far off the chord\n"
            "                      against the outer quarters, 1/256 px at the pass's\n"
            "                      scale, 0 = off (%u)\n"
            "  --merge-gap PX      merge collinear lines up to PX apart (default width/8,\n"
            "                      0 = no merging)\n"
            "  --merge-dev Q8      merge tolerance across the line, 1/256 px (%u)\n"
            "  --field drop|keep|off   field boundary (symline boundary): reported as\n"
            "                      field_boundary; drop: line points above it are not\n"
            "                      traced (default); keep: nothing dropped; off: not\n"
            "                      computed\n"
            "  --field-margin PX   drop keeps points up to PX above the boundary (%u)\n",
            c.radius, c.illumination, c.adaptive ? 1u : 0u, (int)c.bright_sigma10 + 100,
            c.ridge_sigma10, (int)c.side_sigma10 + 100, c.contrast_pct, c.contrast_min,
            c.contrast_asym_pct, c.min_length, c.curve_dev_q8, c.curve_bend_q8, c.merge_dev_q8,
            c.field_margin);
}
