/*
 * Families not written yet answer QC_EUNSUPPORTED. Whoever implements a
 * family deletes its line here.
 */
#include "internal.h"

#define QC__STUB(fn, family)                                                  \
    int fn(qc_ctx *ctx, const qc_region *region, const qc_params *params,     \
           const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out, \
           qc_stats *stats)                                                   \
    {                                                                         \
        (void)region; (void)params; (void)skel; (void)motifs; (void)out;      \
        (void)stats;                                                          \
        return qc__fail(ctx, QC_EUNSUPPORTED, "family %s is not built yet",   \
                        family);                                              \
    }

QC__STUB(qc_deco_spiral, "spiral")
