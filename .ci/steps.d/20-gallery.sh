#!/usr/bin/env bash
# Every gallery spec generates, and every PAT it writes passes quiltc check.
set -euo pipefail
make gallery
for f in build/gallery/*.pat; do
    build/quiltc check "$f" >/dev/null || { echo "not sewable: $f"; build/quiltc check "$f" | head; exit 1; }
done
echo "gallery: $(ls build/gallery/*.pat | wc -l) patterns, all sewable"
