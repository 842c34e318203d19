/*
 * Keeping a decorated path inside its region (keep_inside.c): run by
 * qc_generate after every family, so no family writes a stitch outside.
 */
#ifndef QC_KEEP_INSIDE_H
#define QC_KEEP_INSIDE_H

#include "internal.h"

/* How far a curve may stray over the boundary, mm (a tenth of the 0.02 in
 * that `quiltc check` allows, so flattening and stitching stay within it). */
#define QC__INSIDE_TOL_MM 0.1

/*
 * Rewrites *path so that every point of it lies inside region (holes
 * excluded) or within QC__INSIDE_TOL_MM of its boundary. A cubic that
 * strays has its control points pulled towards its ends (the tangents keep
 * their directions, so the curve stays smooth) until it fits, else it
 * becomes its chord; a chord that strays (a tour arc across a notch or a
 * hole) is replaced by the shortest route inside, round the region's
 * reflex corners; an end point outside (a loop's apex over a seam) moves
 * to the nearest point inside. *fixed (may be NULL) receives the number of
 * commands changed. family names the family in the error. Errors:
 * QC_ERANGE (no route inside joins two points, e.g. islands: the message
 * names the family and the place in mm and inches),
 * QC_ENOMEM (*path is unchanged).
 */
QC__HIDDEN int qc__path_keep_inside(qc_ctx *ctx, const qc_region *region, const char *family,
                                    qc_path *path, size_t *fixed);

#endif
