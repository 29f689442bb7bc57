/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Options of the line-finding method for `symline lines|overlay`.
 */
#include "muffopts.h"

#include <string.h>

#include "detopts.h"

typedef struct muff_opt {
    const char *name;
    uint32_t lo, hi;
    size_t offset; /* into symline_muff_config */
} muff_opt;

static const muff_opt opts[] = {
    {"--cell", 0, 64, offsetof(symline_muff_config, cell)},
    {"--min-votes", 1, 65535, offsetof(symline_muff_config, min_votes)},
    {"--nms", 0, 16, offsetof(symline_muff_config, nms_cells)},
    {"--max-peaks", 1, 1024, offsetof(symline_muff_config, max_peaks)},
    {"--muff-tol", 0, 8192, offsetof(symline_muff_config, tol_q8)},
    {"--muff-gap", 0, 65535, offsetof(symline_muff_config, gap)},
    {"--min-points", 2, 65535, offsetof(symline_muff_config, min_points)},
    {"--min-fill", 0, 100, offsetof(symline_muff_config, min_fill_pct)},
};

void muffopts_init(muffopts *m)
{
    m->muff = 0;
    symline_muff_config_default(&m->mc);
}

/* 1 when argv[*i] was one of these options (value consumed), 0 when not, -1 on a bad value. */
static int muffopts_parse(muffopts *m, int argc, char **argv, int *i, char *err, size_t errlen)
{
    const char *o = argv[*i];
    size_t k;
    if (strcmp(o, "--method") == 0) {
        const char *v = *i + 1 < argc ? argv[*i + 1] : NULL;
        if (v == NULL || (strcmp(v, "muff") != 0 && strcmp(v, "tracer") != 0)) {
            snprintf(err, errlen, "--method needs 'muff' or 'tracer'");
            return -1;
        }
        m->muff = strcmp(v, "muff") == 0;
        (*i)++;
        return 1;
    }
    for (k = 0; k < sizeof opts / sizeof opts[0]; k++) {
        if (strcmp(o, opts[k].name) == 0) {
            uint32_t v;
            if (*i + 1 >= argc || detopts_u32(argv[*i + 1], opts[k].lo, opts[k].hi, &v) != 0) {
                snprintf(err, errlen, "%s needs an integer %u..%u", o, opts[k].lo, opts[k].hi);
                return -1;
            }
            memcpy((char *)&m->mc + opts[k].offset, &v, sizeof v);
            (*i)++;
            return 1;
        }
    }
    return 0;
}

/* Option names without "--": --method, then the table. */
static const char *long_name(size_t k)
{
    return (k == 0u ? "--method" : opts[k - 1u].name) + 2;
}

size_t muffopts_longopts(struct option *out, size_t cap)
{
    size_t k, n = 0;
    for (k = 0; k < 1u + sizeof opts / sizeof opts[0] && n < cap; k++, n++) {
        out[n].name = long_name(k);
        out[n].has_arg = required_argument;
        out[n].flag = NULL;
        out[n].val = MUFFOPTS_VAL + (int)k;
    }
    return n;
}

int muffopts_apply(muffopts *m, int code, const char *arg, char *err, size_t errlen)
{
    /* The argv form with the option and its value, so both parsers share one rule. */
    char name[32];
    char *argv[2];
    int i = 0;
    if (code < MUFFOPTS_VAL || code >= MUFFOPTS_VAL + 1 + (int)(sizeof opts / sizeof opts[0])) {
        return 0;
    }
    snprintf(name, sizeof name, "--%s", long_name((size_t)(code - MUFFOPTS_VAL)));
    argv[0] = name;
    argv[1] = (char *)arg;
    return muffopts_parse(m, 2, argv, &i, err, errlen) == 1 ? 1 : -1;
}

void muffopts_help(FILE *f)
{
    symline_muff_config c;
    symline_muff_config_default(&c);
    fprintf(f,
            "  --method tracer|muff  tracer: trace neighbouring line points (default);\n"
            "                      muff: the Muff-space line finder (the paper's first\n"
            "                      method): line points vote for pairs of border cells,\n"
            "                      peaks become segments\n"
            "  Muff space only (the line filter options above apply to both methods;\n"
            "  --min-length is the shortest segment):\n"
            "  --cell PX           border cell size, 1..64, 0 = width/80 (%u)\n"
            "  --min-votes N       smallest accumulator peak (%u)\n"
            "  --nms N             a peak beats all pairs within N cells at both ends (%u)\n"
            "  --max-peaks N       strongest peaks examined (%u)\n"
            "  --muff-tol Q8       support distance from a line, 1/256 px, 64..8192;\n"
            "                      0 = 3 px * width/640, at least 2 px (%u)\n"
            "  --muff-gap PX       largest gap between a segment's points; 0 = width/32,\n"
            "                      at least 2 x tolerance + 2 px (%u)\n"
            "  --min-points N      fewest points of a segment (%u)\n"
            "  --min-fill PCT      a segment's points cover PCT %% of its length, gaps up\n"
            "                      to width/160 px counted as covered; 0 = off (%u)\n",
            c.cell, c.min_votes, c.nms_cells, c.max_peaks, c.tol_q8, c.gap, c.min_points,
            c.min_fill_pct);
}
