/*
 * The line filter: which S points (symmetry maxima) are line points.
 *
 * A field line is a bright ridge across its direction. The contrast filter
 * asks exactly that of the S point: its gray value must stand above the gray
 * values k = m+1 pixels to both sides. k = m+1 also rejects S points inside
 * regions wider than the operator's reach (those belong to a coarser scale).
 * The ridge height needed and the minimum gray value are set per frame by
 * symline_detect() from the frame's mean and standard deviation (`adaptive`),
 * so scaling or offsetting the brightness leaves the decision unchanged apart
 * from clipping and rounding.
 * The paper's A1-S filter only asks for an A point nearby (done by the
 * caller, which holds the extrema) and an absolute illumination threshold.
 */
#include "detect_internal.h"

void sl_pass_setup(sl_pass *p, const symline_config *cfg, symline_axis axis, uint32_t level,
                   uint32_t width, uint32_t height)
{
    p->axis = axis;
    p->level = level;
    p->w = width >> level;
    p->h = height >> level;
    p->m = cfg->radius;
    p->k = cfg->radius + 1u;
    p->filter = cfg->filter;
    p->a_dist = 0u;
    if (cfg->filter == SYMLINE_FILTER_PAPER) {
        p->a_dist = cfg->a_distance != 0u ? cfg->a_distance : cfg->radius;
    }
    p->lag = cfg->radius;
    p->illum = cfg->illumination;
    p->pct = cfg->contrast_pct;
    p->cmin = cfg->contrast_min;
    p->apct = cfg->contrast_asym_pct;
    p->side_max = 255u;
}
