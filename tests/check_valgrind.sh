#!/bin/sh
# The CLI under valgrind's memcheck: every built family, skeleton, job,
# convert, check, list and a few error paths must run with no memory error
# and no definite leak (--error-exitcode=99), and exit as they do without
# it. Ignored when valgrind is missing or quiltc is an ASan build.
. tests/cli_lib.sh
ROOT=$(pwd)
IGN=0

if ! command -v valgrind >/dev/null 2>&1; then
    printf '\n-----------------------\n1 Tests 0 Failures 1 Ignored\nOK\n'
    echo "valgrind is not installed: skipped"
    exit 0
fi
if nm "$QC" 2>/dev/null | grep -q __asan_init; then
    printf '\n-----------------------\n1 Tests 0 Failures 1 Ignored\nOK\n'
    echo "$QC is an ASan build: valgrind skipped"
    exit 0
fi

# vg STATUS ARGS...: quiltc under memcheck exits with STATUS and memcheck
# reports nothing.
vg() {
    want=$1
    shift
    valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite \
        --log-file="$WORK/.vg" "$QC" "$@" >"$WORK/.vgout" 2>&1
    got=$?
    if [ -s "$WORK/.vg" ]; then echo "memcheck:"; head -n 20 "$WORK/.vg"; return 1; fi
    if [ "$got" -ne "$want" ]; then echo "exit $got, wanted $want"; tail -n 3 "$WORK/.vgout"; return 1; fi
}

built() {
    "$QC" generate --family "$1" --region rect:1x1 -o - --format pat >/dev/null 2>"$WORK/.b"
    ! grep -q 'not built yet' "$WORK/.b"
}

for f in vine branching wanderer pebbling packing fill stipple echo spiral; do
    if built "$f"; then
        check "generate_$f" vg 0 generate --family "$f" --region circle:3 -o "$f.pat" -o "$f.svg"
    else
        T_RUN=$((T_RUN + 1)) IGN=$((IGN + 1))
        echo "$0:$T_RUN:generate_$f:IGNORE: family $f is not built yet"
    fi
done
check generate_motifs_from_svg vg 0 generate --family branching --region heart:4 \
    --motif "leaf,$ROOT/tests/fixtures/svg/heart.svg" -o m.pat
check generate_svg_region_every_format vg 0 generate --region \
    "$ROOT/tests/fixtures/svg/block_with_hole.svg" --units mm --spacing 12 \
    -o a.pat -o a.qli -o a.dxf -o a.plt -o a.qcc -o a.iqp -o a.bqm -o a.gcode -o a.svg --stats
check generate_given_points vg 0 generate --points "$ROOT/tests/fuzz/corpus/points/berlin52.tsp" \
    --units mm --region rect:2000x2000 --family wanderer --spacing 20 --margin 2 -o w.svg # at 100 its loops leave the block
check skeleton_json_and_svg vg 0 skeleton --region square:60 --units mm -o s.json -o s.svg
small_job() {
    cat > job.json <<'JSON'
{"units": "in", "tie": 2, "blocks": [
 {"region": "rect:3x3", "at": [0, 0], "family": "stipple", "params": {"spacing": 0.75}},
 {"region": "circle:3", "at": [5, 0], "rotate": 45, "family": "vine", "params": {"spacing": "20mm"}}]}
JSON
    vg 0 job job.json -o quilt.pat -o quilt.svg
}
check job_two_blocks small_job
check convert_pat_to_svg vg 0 convert "$ROOT/tests/golden/small.pat" c.svg
check convert_svg_to_gcode vg 0 convert "$ROOT/tests/golden/small.svg" c.gcode
check check_generated_pat vg 0 check vine.pat
check check_pat_with_findings vg 1 check "$ROOT/tests/bad/files/bad_decimals.pat"
check list_params vg 0 list params
# error paths
check error_billion_laughs vg 1 generate --region "$ROOT/tests/bad/svg/billion_laughs.svg"
check error_self_crossing vg 1 generate --region "$ROOT/tests/bad/svg/bowtie.svg"
check error_bad_points vg 1 generate --points "$ROOT/tests/bad/files/points_nan.csv"
check error_bad_job vg 2 job "$ROOT/tests/bad/files/job_family.json"
check error_bad_pat vg 1 convert "$ROOT/tests/bad/files/bad_numbering.pat" x.svg
check error_unwritable vg 1 generate -o /nonexistent/x.pat
check error_range vg 2 generate --spacing 0.01mm
check error_too_many_points vg 1 generate --region rect:1000x1000 --spacing 0.5mm

printf '\n-----------------------\n%d Tests %d Failures %d Ignored\n' "$T_RUN" "$T_FAIL" "$IGN"
[ "$T_FAIL" -eq 0 ] && echo OK || echo FAIL
