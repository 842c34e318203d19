#!/bin/sh
# Renders chosen gallery SVGs side by side into docs/gallery.png (for the
# README) with headless Chromium. Run `make gallery` first.
# Usage: gallery/contact.sh NAME...
set -eu
out=docs/gallery.png
page=$(mktemp -d)
trap 'rm -rf "$page"' EXIT
{
    echo '<html><body style="margin:0;background:#fff;font:14px sans-serif">'
    echo '<div style="display:grid;grid-template-columns:repeat(4,300px);gap:8px;padding:8px">'
    for n in "$@"; do
        cp "build/gallery/$n.svg" "$page/"
        echo "<figure style=\"margin:0\"><img src=\"$n.svg\" style=\"width:300px;height:300px;object-fit:contain\"><figcaption>$n</figcaption></figure>"
    done
    echo '</div></body></html>'
} > "$page/index.html"
rows=$(( ($# + 3) / 4 ))
chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$page/profile" --hide-scrollbars --screenshot="$PWD/$out" \
    --window-size=1240,$((rows * 330 + 16)) "file://$page/index.html" 2>/dev/null
echo "wrote $out"
