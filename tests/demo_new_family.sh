#!/bin/sh
# Proof for docs/adding-a-family.md: in a scratch copy of the tracked tree,
# a new family is one new file (src/deco/family_border.c) plus one line in
# QC_FAMILY_MAP, and then the CLI lists it, generates it, and
# tests/test_family.c (which walks qc_family_info) checks it like the others.
# Not part of `make test` (it rebuilds the library from scratch):
#   sh tests/demo_new_family.sh
set -e
ROOT=$(pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$WORK"
cd "$WORK"

cat > src/deco/family_border.c <<'EOF'
/* Border (a demonstration): the block's outer outline, sewn once round. */
#include "internal.h"

static int border_run(qc_ctx *ctx, const qc_region *region, const qc_params *params,
                      const qc_skeleton *skel, const qc_motif_set *motifs, qc_path *out,
                      qc_stats *stats)
{
    size_t i, n = region->ring_end[0];
    int rc = qc_path_move_to(ctx, out, region->v[0]);

    (void)params;
    (void)skel;
    (void)motifs;
    (void)stats;
    for (i = 1; i <= n && rc == QC_OK; i++)
        rc = qc_path_line_to(ctx, out, region->v[i % n]);
    return rc;
}

const qc_family_desc qc__family_border = {
    QC_FAMILY_BORDER, "border", "the block's outline, sewn once round", 0, 0, border_run, NULL};
EOF
sed -i 's|^    /\* a new family: one line above this one \*/$|    X(BORDER, border)                                                       \\\n&|' \
    include/quiltc/pattern.h

echo "== the change: one new file, and include/quiltc/pattern.h gains one line:"
ls src/deco/family_border.c
diff "$ROOT/include/quiltc/pattern.h" include/quiltc/pattern.h || true

make -s -j2 WERROR=1 build/quiltc build/tests/test_family >/dev/null
echo "== quiltc list families:"
build/quiltc list families | tr '\n' ' '
echo
build/quiltc generate -q --family border --region heart:8 -o "$WORK/border.pat"
echo "== quiltc generate --family border: $(wc -c < "$WORK/border.pat") bytes of PAT"
build/tests/test_family | tail -2
