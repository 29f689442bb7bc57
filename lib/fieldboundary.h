/*
 * The field boundary stage (fieldboundary.c): private interface for the
 * detector, which runs the stage before its passes and drops line points
 * above the boundary. Not part of the public API.
 */
#ifndef SYMLINE_FIELDBOUNDARY_H
#define SYMLINE_FIELDBOUNDARY_H

#include "symline/field.h"
#include "common.h"

/* Grid step for a frame `width` wide under fc (fc->cell or the automatic one). */
uint32_t sl_field_cell(uint32_t width, const symline_field_config *fc);

/* symline_field_find() without the argument checks (valid image, config,
 * workspace of symline_field_workspace_size() bytes). */
void sl_field_run(const symline_image *img, const symline_field_config *fc, uint8_t *ws,
                  size_t ws_size, symline_field_boundary *out);

#endif /* SYMLINE_FIELDBOUNDARY_H */
