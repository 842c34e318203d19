/* Pieced shapes as a quilter cuts them (issue 16's corpus), built in code, in mm. */
#ifndef PIECED_H
#define PIECED_H

#include "quiltc.h"

typedef struct pieced_shape {
    const char *name;
    int sharp; /* has a point sharper than 60 deg (the farthest-fabric goal skips these) */
} pieced_shape;

/* The corpus; *count receives its length. */
const pieced_shape *pieced_shapes(size_t *count);
/* Builds shape k, normalized, lower-left at (0, 0). QC_OK or an error. */
int pieced_build(qc_ctx *ctx, size_t k, qc_region *out);

#endif
