#!/bin/sh
# generate's placement, stitch-estimate and word options (issue 19):
# --rotate/--mirror/--at/--clip, --spi/--speed/--bobbin-yards, the written
# summary on stderr and -q, exact long option names, G-code pen lines.
. tests/cli_lib.sh
ROOT=$(pwd)

# points of a .gcode as "x y jump" lines (mm)
gpoints() {
    python3 - "$1" <<'PY'
import sys
up = False
for l in open(sys.argv[1]):
    w = dict((t[0], t[1:]) for t in l.split() if t[0] in 'GXYZ')
    if 'Z' in w: up = float(w['Z']) > 0
    if 'X' in w: print(w['X'], w['Y'], 1 if (w.get('G') == '0' or up) else 0)
PY
}

# The default place is the origin and changes no byte; --at moves every
# point by exactly (X, Y); --mirror x then --rotate 180 is --mirror y.
placed_exactly() {
    "$QC" generate -q --seed 4 -o a.gcode && "$QC" generate -q --seed 4 --at 0,0 -o b.gcode &&
        cmp a.gcode b.gcode && "$QC" generate -q --seed 4 --at 2,1.5 -o c.gcode &&
        "$QC" generate -q --seed 4 --mirror x --rotate 180 -o d.gcode &&
        "$QC" generate -q --seed 4 --mirror y -o e.gcode && cmp d.gcode e.gcode &&
        ! cmp -s a.gcode e.gcode && gpoints a.gcode > a.txt && gpoints c.gcode > c.txt &&
        python3 - <<'PY'
a = [tuple(map(float, l.split())) for l in open('a.txt')]
c = [tuple(map(float, l.split())) for l in open('c.txt')]
assert len(a) == len(c) > 100, (len(a), len(c))
for p, q in zip(a, c):
    assert abs(q[0] - p[0] - 50.8) < 0.0011 and abs(q[1] - p[1] - 38.1) < 0.0011 and p[2] == q[2], (p, q)
PY
}
check at_moves_by_exactly_x_y_and_mirrors_compose placed_exactly

# A quarter turn of an 8x4 in block: the outline becomes 4 wide, 8 tall,
# with its corner at --at; the svg preview outline turns with it.
quarter_turn() {
    "$QC" generate -q --region rect:8x4 -o s.svg &&
        "$QC" generate -q --region rect:8x4 --rotate 90 --at 1,1 -o t.pat -o t.svg &&
        "$QC" check t.pat --region rect:5x9 | grep -q sewable &&
        ! "$QC" check t.pat --region rect:4x8 >/dev/null &&
        grep -q 'width="8.1575in" height="4.1575in"' s.svg &&
        grep -q 'width="4.1575in" height="8.1575in"' t.svg || {
            grep -o 'width="[^"]*" height="[^"]*"' s.svg t.svg; return 1; }
}
check rotate_90_turns_the_block_and_its_outline quarter_turn

# A .pat cannot go negative: the error names --at in the user's units.
at_negative() {
    d=$(mktemp -d "$WORK/neg.XXXXXX") && cd "$d" || return 1
    expect_fail 2 "^quiltc: --at -1,0 in puts the pattern's lower-left at (-0.9" "$QC" generate -o n.pat --at -1,0 &&
        [ -z "$(ls -A)" ] && "$QC" generate -q -o n.svg --at -1,0 && [ -s n.svg ]
}
check at_negative_is_refused_for_pat_only at_negative

# --clip crops at the seam: with it no point of a zero-margin branching
# pattern is beyond the circle's outline. (Without it the keep-inside pass
# now keeps this one within 0.002 mm too; --clip cuts exactly.)
clipped() {
    for c in "" --clip; do
        "$QC" generate -q $c --family branching --margin 0 --region circle:4 -o "o$c.gcode" || return 1
        gpoints "o$c.gcode" > "o$c.txt"
    done
    python3 - <<'PY'
import math
def worst(f):
    pts = [tuple(map(float, l.split())) for l in open(f)]
    return max(math.hypot(x - 50.8, y - 50.8) for x, y, _ in pts), sum(j for _, _, j in pts)
w0, j0 = worst('o.txt')
w1, j1 = worst('o--clip.txt')
assert w0 < 50.8 + 0.5, w0
assert w1 <= 50.8 + 0.001 and j1 >= j0, (w1, j1, j0)
PY
}
check clip_crops_at_the_outline clipped

# "stitches" is length x spi in check, --stats and the written line alike.
stitches_agree() {
    "$QC" generate --seed 2 -o s.pat --spi 16 --stats 2> err.txt &&
        [ "$(wc -l < err.txt)" -eq 2 ] &&
        s=$(tail -n 1 err.txt | python3 -c 'import json,sys; print(json.load(sys.stdin)["stitches"])') &&
        head -n 1 err.txt | grep -q "^wrote s.pat (pat): $s stitches at 16 spi" &&
        c=$("$QC" check s.pat --spi 16 | sed -n 's/^stitches: \([0-9]*\) at 16 spi.*/\1/p') &&
        [ -n "$c" ] && [ $((c - s)) -le 1 ] && [ $((s - c)) -le 1 ] &&
        h=$("$QC" check s.pat | sed -n 's/^stitches: \([0-9]*\) at 12 spi.*/\1/p') &&
        [ $((h * 16 / 12 - c)) -le 2 ] && [ $((c - h * 16 / 12)) -le 2 ] || {
            cat err.txt; echo "stats $s check $c at 12: $h"; return 1; }
}
check stitches_mean_length_times_spi_everywhere stitches_agree

estimates() {
    "$QC" generate -q --seed 2 -o a.pat --stats 2> a.json &&
        "$QC" generate -q --seed 2 -o b.pat --stitch-length 2mm --speed 50mm --bobbin-yards 10 --stats 2> b.json &&
        cmp a.pat b.pat && python3 - <<'PY'
import json
a, b = json.load(open('a.json')), json.load(open('b.json'))
assert a['spi'] == 12 and abs(b['spi'] - 12.7) < 1e-9, (a['spi'], b['spi'])
assert abs(b['stitches'] - a['stitches'] * 12.7 / 12) <= 1, (a['stitches'], b['stitches'])
assert abs(b['sew_seconds'] - a['sew_seconds'] * 25.4 / 50) < 1e-6 * a['sew_seconds'], (a, b)
assert 'bobbins' not in a and b['bobbins'] > 0, b
PY
}
check spi_speed_and_bobbins_change_only_the_estimate estimates

# --tie-length sets the tie-off stitches' length.
tie_length() {
    "$QC" generate -q --tie 2 --tie-length 0.3mm -o t.gcode && gpoints t.gcode > t.txt &&
        python3 - <<'PY'
import math
p = [tuple(map(float, l.split())) for l in open('t.txt')]
d = math.hypot(p[1][0] - p[0][0], p[1][1] - p[0][1])
assert abs(d - 0.3) < 0.002, d
PY
}
check tie_length_sets_the_tie_stitch tie_length

quiet() {
    "$QC" generate -q -o a.pat -o a.svg 2> q.txt && [ ! -s q.txt ] &&
        "$QC" generate -o a.pat -o a.svg 2> w.txt && "$QC" generate -o - --format svg 2>> w.txt > /dev/null &&
        [ "$(wc -l < w.txt)" -eq 3 ] && grep -q '^wrote a.pat (pat): [0-9]* stitches at 12 spi, [0-9.]* yd of thread, about [0-9]* min [0-9][0-9] s$' w.txt &&
        grep -q '^wrote stdout (svg)' w.txt &&
        "$QC" generate --units mm --region rect:200x200 -o m.pat 2>&1 | grep -q ' m of thread' || { cat w.txt; return 1; }
}
check one_line_per_written_file_and_q_silences quiet

# job and convert say what they wrote as generate does; -q silences them.
job_convert_say() {
    echo '{"blocks": [{"region": "rect:2x2"}, {"region": "rect:2x2", "at": [2, 0]}]}' > j.json &&
        "$QC" job j.json -o q.pat -o q.svg 2> j.txt && [ "$(wc -l < j.txt)" -eq 2 ] &&
        s=$(sed -n 's/^wrote q.pat (pat): \([0-9]*\) stitches at 12 spi, [0-9.]* yd of thread, about [0-9]* min [0-9][0-9] s$/\1/p' j.txt) &&
        grep -q "^wrote q.svg (svg): $s stitches" j.txt &&
        c=$("$QC" check q.pat | sed -n 's/^stitches: \([0-9]*\) at 12 spi.*/\1/p') &&
        [ -n "$s" ] && [ $((c - s)) -le 1 ] && [ $((s - c)) -le 1 ] &&
        "$QC" convert q.pat q.dxf 2> c.txt && [ "$(wc -l < c.txt)" -eq 1 ] &&
        grep -q '^wrote q.dxf (dxf): [0-9]* stitches at 12 spi, [0-9.]* yd of thread' c.txt &&
        "$QC" job -q j.json -o r.pat 2> qj.txt && [ ! -s qj.txt ] && cmp q.pat r.pat &&
        "$QC" convert q.pat r.dxf --quiet 2> qc.txt && [ ! -s qc.txt ] && cmp q.dxf r.dxf ||
        { cat j.txt c.txt qj.txt qc.txt; echo "job $s check $c"; return 1; }
}
check job_and_convert_say_what_they_wrote job_convert_say

# --split-stitches: no sewn segment longer than one stitch (1/spi in), for
# machines without a stitch regulator; without it long lines stay whole.
split_stitches() {
    longest() { gpoints "$1" | python3 -c '
import sys, math
p = [tuple(map(float, l.split())) for l in sys.stdin]
print(max(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(p, p[1:]) if b[2] == 0))'; }
    "$QC" generate -q --family echo --region rect:4x4 --spi 10 -o n.gcode &&
        "$QC" generate -q --family echo --region rect:4x4 --spi 10 --split-stitches -o s.gcode -o s.pat &&
        "$QC" generate -q --family stipple --stitch-length 3mm --split-stitches --tie 3 -o t.gcode &&
        "$QC" generate -q --family pebbling --region rect:2x2 --spi 100 --split-stitches -o h.gcode &&
        "$QC" check s.pat > c.txt && n=$(longest n.gcode) && s=$(longest s.gcode) &&
        t=$(longest t.gcode) && h=$(longest h.gcode) &&
        python3 -c "assert $n > 10 and 2.4 < $s <= 2.541 and 2.9 < $t <= 3.001 and $h <= 0.2551, ($n, $s, $t, $h)" &&
        grep -q '^segment lengths: [0-9.]* \.\. 2\.54[0-9]* mm$' c.txt || { cat c.txt; echo "$n $s $t $h"; return 1; }
}
check split_stitches_caps_every_stitch split_stitches

# G-code lifts the pen for each jump by default; commands of one's own; ''.
pen() {
    "$QC" generate -q --family pebbling --region rect:3x2 --tie 0 -o p.gcode &&
        grep -q '^G0 Z5$' p.gcode && grep -q '^G1 Z0$' p.gcode &&
        "$QC" generate -q --family pebbling --region rect:3x2 -o m.gcode --pen-up M5 --pen-down M3 &&
        ! grep -q Z m.gcode && grep -q '^M5$' m.gcode &&
        "$QC" generate -q --family pebbling --region rect:3x2 -o n.gcode --pen-up '' --pen-down '' &&
        ! grep -q 'Z\|^M[35]' n.gcode && "$QC" convert p.gcode p.pat && "$QC" convert n.gcode n.pat &&
        cmp p.pat n.pat
}
check gcode_pen_lines_round_trip pen

# Sizes with their own unit, --units inch, and quiltc list alone.
words() {
    "$QC" generate -q --seed 5 -o a.pat && "$QC" generate -q --seed 5 --units mm --region rect:8x8in -o b.pat &&
        cmp a.pat b.pat && "$QC" generate -q --seed 5 --units inch -o c.pat && cmp a.pat c.pat &&
        "$QC" generate -q --seed 5 --region rect:20.32x20.32cm -o d.pat && cmp a.pat d.pat &&
        "$QC" list > l.txt && grep -q '^  families' l.txt && grep -q '^  formats' l.txt
}
check shape_units_inch_and_list_alone words

# skeleton --points without --region: the points' own box, grown by the margin.
skeleton_points() {
    "$QC" skeleton --points "$ROOT/tests/data/tsplib/berlin52.tsp" --units mm -o b.json &&
        python3 -c '
import json
s = json.load(open("b.json"))
assert len(s["points"]) == 52 and len(s["edges"]) == 51, (len(s["points"]), len(s["edges"]))
assert [565.0, 575.0] in s["points"], s["points"][:3]
'
}
check skeleton_points_need_no_region skeleton_points

finish
