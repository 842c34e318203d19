/* Thread over an earlier pass, for the coverage tests. */
#ifndef RETRACE_H
#define RETRACE_H

#include "quiltc.h"

/* Pieces of p as qc_fabric_measure. *share: fraction of the path within
 * 0.01 in of a pass more than 0.3 in earlier; *passes: the most passes over
 * one spot (1 = never retraced). 0, or -1 when out of memory. */
int retrace_measure(const qc_vec2 *p, size_t n, const uint32_t *ends, size_t nends,
                    double *share, size_t *passes);

#endif
