/*
 * Repeatable tiles (paper §7.1, Fig. 27): a tile's path enters on its left
 * edge and leaves at the mirrored point of its right edge, so copies laid
 * side by side join into one continuous pantograph row. The fill, stipple,
 * branching and meander families build such tiles when params.tile is
 * edge-to-edge or all-over and lay them out repeat_cols x repeat_rows
 * themselves (qc_tile_layout: one piece per row).
 */
#ifndef QUILTC_TILE_H
#define QUILTC_TILE_H

#include "core.h"
#include "region.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * The tile's entry and exit: where the horizontal line through the middle
 * of region's bounding box first enters and last leaves the region (for a
 * rectangle, the midpoints of its left and right sides). The exit is the
 * entry moved by the tile's width, so *exit - *entry == (box width, 0).
 * Errors: QC_EINVAL (no ring, the line misses the region, or it does not
 * reach both sides of the box: the exit would lie outside the region).
 */
int qc_tile_ports(qc_ctx *ctx, const qc_region *region, qc_vec2 *entry, qc_vec2 *exit);

/*
 * Appends cols x rows copies of tile (one piece, from its entry to its exit
 * = entry + (dx, 0)) to out, as a long-arm sews a pantograph: row r is
 * moved down by r * dy mm and runs left to right for even r, right to left
 * (the tile reversed) for odd r, so each row starts on the side where the
 * one before ended; each row is its own piece (a MOVE: the row change is a
 * jump, as the quilt is rolled on between rows and each row tied off).
 * Odd rows are also moved right by offset * dx (0 <= offset < 1: 0.5 is a
 * half-drop brick layout). Within a row each copy's first point is
 * replaced by the previous copy's last point, so the joins are exact.
 * The copies may hold at most QC_MAX_TILED_POINTS path points, checked
 * before anything is appended (a 100 x 100 repeat of a dense tile would
 * take gigabytes before the stitch plan's own limit).
 * Errors: QC_EINVAL (tile empty or not one piece, cols or rows 0, dx/dy
 * not finite, offset outside [0, 1)), QC_ELIMIT (over the budget),
 * QC_ENOMEM (out as on entry, core.h).
 */
#define QC_MAX_TILED_POINTS 4000000u /* path points of all copies: 64 MB */
int qc_tile_layout(qc_ctx *ctx, const qc_path *tile, double dx, double dy, unsigned cols,
                   unsigned rows, double offset, qc_path *out);
/* The same rows without offset, joined into one piece by a line along the
 * outer side edge (the layout before qc_tile_layout). */
int qc_tile_repeat(qc_ctx *ctx, const qc_path *tile, double dx, double dy, unsigned cols,
                   unsigned rows, qc_path *out);

#ifdef __cplusplus
}
#endif
#endif
