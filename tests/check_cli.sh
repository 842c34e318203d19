#!/bin/sh
# quiltc end to end: the README's default run, PAT dialect, determinism,
# stats, every usage and runtime error (one line, right status, no file).
. tests/cli_lib.sh
ROOT=$(pwd)

# The PAT dialect of the foundation issue, checked line by line.
pat_dialect() {
    python3 - "$1" <<'PY'
import re, sys
data = open(sys.argv[1], 'rb').read()
assert data.endswith(b'\r\n'), 'no final CRLF'
lines = data[:-2].split(b'\r\n')
assert all(b'\n' not in l and b'\r' not in l for l in lines), 'bare LF or CR'
for i, l in enumerate(lines[:-1], 1):
    cmd = b'G00' if i == 1 else b'G01'
    m = re.fullmatch(rb'N(\d+)' + cmd + rb'X(\d+\.\d{3})Y(\d+\.\d{3})', l)
    assert m, 'line %d: %r' % (i, l)
    assert int(m.group(1)) == i, 'numbering at line %d' % i
    x, y = float(m.group(2)), float(m.group(3))
    assert 0 <= x <= 8.0 and 0 <= y <= 8.0, 'outside the 8 in block: %r' % l
    if i > 1:
        assert (m.group(2), m.group(3)) != prev, 'repeated point at line %d' % i
    prev = (m.group(2), m.group(3))
assert lines[-1] == b'N%dM02' % len(lines), 'last line %r' % lines[-1]
assert len(lines) > 500, 'only %d lines' % len(lines)
PY
}

default_run() {
    "$QC" generate && pat_dialect pattern.pat && grep -q '<svg' pattern.svg &&
        grep -q 'width="8[.0-9]*in"' pattern.svg && "$QC" check pattern.pat >/dev/null
}
check default_writes_pat_and_svg_of_an_8in_block default_run

same_bytes() {
    "$QC" generate -o a.pat --seed 7 && "$QC" generate -o b.pat --seed 7 && cmp a.pat b.pat &&
        "$QC" generate -o c.pat --seed 8 && ! cmp -s a.pat c.pat
}
check same_seed_same_bytes_other_seed_differs same_bytes

# The figures (largest gap, farthest fabric) are measured only for --stats:
# the pattern is the same bytes with and without them.
figures_when_asked() {
    "$QC" generate -o s.pat --family fill --stats 2>s.json &&
        "$QC" generate -o n.pat --family fill && cmp s.pat n.pat &&
        grep -q '"farthest_fabric_mm":[1-9]' s.json && grep -q '"largest_gap_mm":[1-9]' s.json
}
check figures_only_for_stats_same_pattern figures_when_asked

units_agree() {
    "$QC" generate -o a.pat --spacing 10mm --region rect:8x8 &&
        "$QC" generate -o b.pat --units mm --spacing 10 --region rect:203.2x203.2 && cmp a.pat b.pat
}
check suffixed_lengths_equal_units_mm units_agree

stdout_matches_file() {
    "$QC" generate -o a.pat && "$QC" generate -o - --format pat > b.pat && cmp a.pat b.pat
}
check stdout_output_matches_the_file stdout_matches_file

stats_json() {
    "$QC" generate --family branching --region heart:8 -o h.pat --stats 2> stats.json &&
        python3 -c '
import json, sys
s = json.loads(open("stats.json").read().splitlines()[-1])  # after the "wrote" line
assert s["family"] == "branching" and s["pieces"] == 1, s
assert s["points"] > 20 and s["edges"] == s["points"] - 1 and s["order"] == 2 * s["edges"] + 1, s
assert s["length_mm"] > 1000 and s["stitches"] > 100 and s["thread_mm"] > s["length_mm"], s
assert s["motifs_placed"] > 0, s
assert set(s["ms"]) >= {"sample", "graph", "tour", "decorate", "plan", "write", "total"}, s["ms"]
assert abs(sum(v for k, v in s["ms"].items() if k != "total") - s["ms"]["total"]) < 0.01, s["ms"]
'
}
check stats_is_one_json_object stats_json

every_family() {
    for f in vine branching wanderer pebbling packing fill stipple echo spiral; do
        "$QC" generate --family "$f" --region circle:6 -o "$f.pat" || return 1
        "$QC" check "$f.pat" >/dev/null || return 1
    done
}
check families_write_sewable_pat every_family

svg_region() {
    "$QC" generate --region "$ROOT/tests/fixtures/svg/block_with_hole.svg" --units mm \
        --spacing 8 -o hole.pat && "$QC" check hole.pat >/dev/null
}
check svg_region_with_a_hole svg_region

skeleton_json() {
    "$QC" skeleton --region square:60 --units mm --points square --spacing 10 -o s.json &&
        python3 -c '
import json
s = json.load(open("s.json"))
n = len(s["points"])
assert s["units"] == "mm" and n > 10, s
assert len(s["edges"]) == n - 1 and len(s["order"]) == 2 * (n - 1) + 1, s
p = s["points"]
tree = sum(((p[a][0] - p[b][0]) ** 2 + (p[a][1] - p[b][1]) ** 2) ** 0.5 for a, b in s["edges"])
assert abs(s["length_mm"] - 2 * tree) < 1e-6, (s["length_mm"], tree)  # the walk runs every edge twice
' && "$QC" skeleton --region square:60 --units mm -o s.svg && grep -q '<circle' s.svg &&
        "$QC" skeleton --region square:60 --units mm --points square --spacing 10 -o t.json \
            -o t.svg && cmp s.json t.json && grep -q '<circle' t.svg
}
check skeleton_json_walks_the_tree skeleton_json

skeleton_golden() {
    "$QC" skeleton --region square:40 --units mm --points square --spacing 10 --margin 2 -o - |
        cmp - "$ROOT/tests/golden/skeleton-small.json"
}
check skeleton_matches_golden skeleton_golden

# berlin52 (TSPLIB, proven optimum 7542): the built-in tour is within 2 %.
tsplib_tour() {
    f="$ROOT/tests/data/tsplib/berlin52.tsp"
    "$QC" skeleton --points "$f" --units mm --region rect:2000x2000 --path tsp -o b.json &&
        python3 -c '
import json
s = json.load(open("b.json"))
assert len(s["points"]) == 52 and sorted(s["order"]) == list(range(52)), s["order"]
assert s["length_mm"] < 7542 * 1.02, s["length_mm"]
'
}
check tsplib_berlin52_tour_near_optimal tsplib_tour

# a280's default tour (greedy, 2-opt, Or-opt, Or-3opt, its kicks), byte for
# byte: speed work on src/tour/ must keep the tours (docs/performance.md,
# "Tours"); a change meant to alter them regenerates the file with this
# command and says why.
tour_golden() {
    "$QC" skeleton --points "$ROOT/tests/data/tsplib/a280.tsp" --units mm --region rect:400x400 \
        --path tsp -o - | cmp - "$ROOT/tests/golden/tour-a280.json"
}
check tsp_tour_matches_golden tour_golden

motif_library() {
    [ "$("$QC" motifs | wc -l)" -ge 16 ] && "$QC" motifs | grep -q '^loop60 .*two legs' &&
        "$QC" motifs --svg leaf -o leaf.svg && grep -q '<path' leaf.svg &&
        expect_fail 2 "unknown motif" "$QC" motifs --svg nosuch &&
        "$QC" generate --family branching --help | grep -q -- '--angle' &&
        ! "$QC" generate --family branching --help | grep -q -- '--tangent'
}
check motifs_listed_and_drawn_family_help motif_library

repeat_alias() {
    "$QC" generate --family stipple --region rect:4x4 --tile edge-to-edge --repeat 3x2 --tie 3 -o a.pat &&
        "$QC" generate --family stipple --region rect:4x4 --tile edge-to-edge --repeat-cols 3 \
            --repeat-rows 2 --tie 3 -o b.pat && cmp a.pat b.pat && "$QC" check a.pat --region rect:12x8 >/dev/null &&
        expect_fail 2 "'3by2' is not COLSxROWS" "$QC" generate --repeat 3by2
}
check repeat_cxr_equals_cols_and_rows repeat_alias

no_concorde() {
    PATH=/usr/bin:/bin expect_fail 1 "no 'concorde' program on PATH" "$QC" skeleton --path tsp --tsp concorde
}
check concorde_missing_says_how_to_get_it no_concorde

help_and_version() {
    "$QC" --help | grep -q generate && "$QC" generate --help | grep -q -- '--spacing' &&
        "$QC" --version | grep -q '^quiltc [0-9]' && "$QC" list families | grep -q stipple &&
        "$QC" list params | grep -q '^spacing'
}
check help_version_and_lists help_and_version

# list params --units speaks the units generate's range errors speak.
params_in_units() {
    "$QC" list params --units inch > in.txt && "$QC" list params --units mm > mm.txt &&
        "$QC" list params > raw.txt && cmp mm.txt raw.txt &&
        grep -q '^spacing  *in  *\[0.01969, 39.37\] default 0.5  ' in.txt &&
        grep -q '^margin  *in  *\[0, 39.37\] default 0.3 d ' in.txt &&
        grep -q '^angle  *deg  *\[-90, 90\] default 45 ' in.txt &&
        grep -q '^spacing  *mm  *\[0.5, 1000\] default 12.7 ' mm.txt &&
        "$QC" list params --units cm | grep -q '^spacing  *cm  *\[0.05, 100\] default 1.27 ' &&
        ! "$QC" generate --spacing 50 2> e.txt && grep -q '\[0.01969, 39.37\] in' e.txt &&
        expect_fail 2 "unknown unit 'ft'" "$QC" list params --units ft || { cat in.txt; return 1; }
}
check list_params_speaks_the_units params_in_units

# Options the family does not read: one warning line, exit 0, the same pattern.
ignored_options() {
    "$QC" generate -q --family vine --seed 4 -o a.pat 2> a.txt && [ ! -s a.txt ] &&
        "$QC" generate -q --family vine --seed 4 --motif leaf -o b.pat 2> b.txt && cmp a.pat b.pat &&
        [ "$(cat b.txt)" = "quiltc: warning: --motif is ignored by family vine" ] &&
        "$QC" generate -q --family vine --motif leaf --angle 3 --repeat 2x2 -o c.pat 2> c.txt &&
        [ "$(cat c.txt)" = "quiltc: warning: --motif, --angle and --repeat are ignored by family vine" ] &&
        "$QC" generate -q --family branching --motif leaf --angle 30 --repeat 2x1 --tile edge-to-edge \
            --region rect:3x3 -o d.pat 2> d.txt && [ ! -s d.txt ] &&
        echo '{"blocks": [{"region": "rect:2x2", "family": "echo", "motif": "leaf", "params": {"angle": 3}}]}' > j.json &&
        "$QC" job -q j.json -o j.pat 2> j.txt &&
        [ "$(cat j.txt)" = "quiltc: warning: job: blocks[0]: motif and params.angle are ignored by family echo" ] ||
        { cat a.txt b.txt c.txt d.txt j.txt; return 1; }
}
check ignored_options_are_one_warning_line ignored_options

# Block outlines on their own layer: DXF layer OUTLINES (read by ezdxf; not
# sewn when quiltc reads the file back) and the SVG's region layer, for
# generate and job.
outline_layers() {
    "$QC" generate -q --region heart:6 --seed 2 -o h.dxf -o h.pat &&
        "$QC" job -q "$ROOT/examples/quilt.json" -o q.dxf -o q.svg -o q.pat &&
        python3 - <<'PY' || return 1
import ezdxf
for name, outlines in (("h.dxf", 1), ("q.dxf", 4)):
    msp = ezdxf.readfile(name).modelspace()
    lines = [e for e in msp if e.dxftype() == "POLYLINE"]
    out = [e for e in lines if e.dxf.layer == "OUTLINES"]
    assert len(out) == outlines and all(e.is_closed for e in out), (name, len(out))
    assert all(len(list(e.points())) >= 4 for e in out), name
    assert any(e.dxf.layer == "0" for e in lines), name
# the quilt's outlines are the four blocks of examples/quilt.json: 16 in x 16 in
pts = [p for e in ezdxf.readfile("q.dxf").modelspace() if e.dxf.layer == "OUTLINES" for p in e.points()]
xs, ys = [p[0] for p in pts], [p[1] for p in pts]
assert abs(min(xs)) < 0.01 and abs(max(xs) - 406.4) < 0.01 and abs(max(ys) - 406.4) < 0.01, (min(xs), max(xs), max(ys))
PY
    grep -q '<g id="region"' q.svg && "$QC" convert -q h.dxf h2.pat && "$QC" convert -q q.dxf q2.pat &&
        [ "$("$QC" check h2.pat | head -n 1)" = "$("$QC" check h.pat | head -n 1)" ] &&
        [ "$("$QC" check q2.pat | head -n 1)" = "$("$QC" check q.pat | head -n 1)" ]
}
check outlines_on_their_own_layer outline_layers

# Pantographs: each row its own piece (a jump between rows, tied off with
# --tie), rows alternating sides, --offset moves every other row, and
# --quilt-width picks the columns that fit.
pantograph_rows() {
    "$QC" generate --family stipple --region rect:4x4 --tile edge-to-edge --repeat 3x3 --spacing 0.5 \
        --seed 27 -o u.pat 2> u.txt &&
        grep -q "warning: the pattern's 3 rows are joined by jumps without tie-offs; --tie 3" u.txt &&
        "$QC" generate -q --family stipple --region rect:4x4 --tile edge-to-edge --repeat 3x3 --spacing 0.5 \
            --seed 27 --tie 3 -o t.pat -o t.gcode 2> t.txt && [ ! -s t.txt ] &&
        "$QC" check t.pat > c.txt && grep -q '^thread cuts (jumps with a tie-off on both sides): 2$' c.txt &&
        grep -q 'bbox: 0.000 [0-9.]* 12.000 ' c.txt &&
        "$QC" generate -q --family branching --region rect:4x4 --tile all-over --repeat-rows 2 --quilt-width 15 \
            --offset 0.5 --spacing 0.6 --seed 27 --tie 3 -o o.pat -o o.gcode &&
        "$QC" check o.pat > d.txt && grep -q 'bbox: 0.000 [0-9.]* 14.000 ' d.txt && grep -q 'sewable' d.txt &&
        python3 - <<'PY' || { cat c.txt d.txt; return 1; }
def rows(name):
    out, cur, up = [], None, False
    for l in open(name):
        w = dict((t[0], t[1:]) for t in l.split() if t[0] in 'GXYZ')
        if 'Z' in w:
            up = float(w['Z']) > 0
        if 'X' in w:
            p = (float(w['X']) / 25.4, float(w['Y']) / 25.4)
            if up or w.get('G') == '0' or cur is None:
                cur = []
                out.append(cur)
            cur.append(p)
    return out
r = rows('t.gcode')
assert len(r) == 3, len(r)
# serpentine: row 0 left to right, row 1 back from the right, row 2 from the left
# (a tie-off of 3 ends 0.5 mm back along the row)
assert r[0][0][0] < 0.01 and r[0][-1][0] > 11.95 and r[1][0][0] > 11.99 and r[1][-1][0] < 0.05, (r[0][0], r[0][-1], r[1][0])
assert r[2][0][0] < 0.01 and abs(r[1][0][1] - r[0][-1][1] + 4) < 0.05, (r[1][0], r[0][-1])
o = rows('o.gcode')
assert len(o) == 2, len(o)
# three 4 in columns fit 15 in with the lower row half a tile over: 0..12 and 2..14
xs0, xs1 = [p[0] for p in o[0]], [p[0] for p in o[1]]
assert min(xs0) > -0.01 and max(xs0) < 12.01 and min(xs1) > 1.99 and max(xs1) < 14.01, (min(xs1), max(xs1))
assert abs(o[1][0][0] - 14) < 0.01 and abs(o[1][-1][0] - 2) < 0.05, (o[1][0], o[1][-1])
PY
    expect_fail 2 "quilt-width lays out pantograph rows" "$QC" generate --quilt-width 20 &&
        expect_fail 2 "a tile of 8 in fits 0 times across" "$QC" generate --tile edge-to-edge --quilt-width 5 &&
        expect_fail 2 "not both" "$QC" generate --tile edge-to-edge --quilt-width 20 --repeat 2x1 &&
        expect_fail 2 "offset 1 ratio out of range" "$QC" generate --tile edge-to-edge --offset 1 &&
        expect_fail 2 "not its full width 0..254 mm" "$QC" generate --region heart:10 --tile all-over
}
check pantograph_rows_offset_and_quilt_width pantograph_rows

# A quilt of four blocks: one file, three jumps, tie-offs at both ends of each block.
job_four_blocks() {
    "$QC" job "$ROOT/examples/quilt.json" -o quilt.pat &&
        "$QC" check quilt.pat --max-jumps 3 | grep -q "jumps: 3" || return 1
    python3 - <<'PY'
import re
lines = open('quilt.pat', 'rb').read().split(b'\r\n')[:-2]
pts = [(re.search(rb'G0(\d)X([\d.]+)Y([\d.]+)', l).groups()) for l in lines]
jumps = [i for i, p in enumerate(pts) if p[0] == b'0']
assert len(jumps) == 4 and jumps[0] == 0, 'G00 at %r' % jumps
xy = [(float(p[1]), float(p[2])) for p in pts]
near = lambda a, b: abs(a[0] - b[0]) <= 0.03 and abs(a[1] - b[1]) <= 0.03
ends = [j - 1 for j in jumps[1:]] + [len(xy) - 1]
for s, e in zip(jumps, ends):
    assert all(near(xy[s], xy[s + k]) for k in (1, 2, 3)), 'no tie-off at line %d' % (s + 1)
    assert all(near(xy[e], xy[e - k]) for k in (1, 2, 3)), 'no tie-off before line %d' % (e + 1)
PY
}
check job_of_four_blocks_has_three_jumps_and_tie_offs job_four_blocks

job_errors() {
    d=$(mktemp -d "$WORK/job.XXXXXX") && cd "$d" || return 1
    echo '{"blocks": [{"region": "rect:4x4", "colour": "red"}]}' > k.json
    expect_fail 2 "blocks\[0\].colour: unknown key" "$QC" job k.json || return 1
    echo '{"blocks": [{"at": [1]}]}' > t.json
    expect_fail 2 "blocks\[0\].at: expected \[x, y\]" "$QC" job t.json || return 1
    echo '{"blocks": [{"params": {"spacingg": 3}}]}' > p.json
    expect_fail 2 "params.spacingg: unknown parameter" "$QC" job p.json || return 1
    echo '{"blocks": [{"params": {"spacing": 0}}]}' > r.json
    expect_fail 2 "spacing 0 in (0 mm) out of range" "$QC" job r.json || return 1
    echo '{"blocks": [' > m.json
    expect_fail 2 "malformed JSON at byte" "$QC" job m.json || return 1
    echo '{"blocks": []}' > e.json
    expect_fail 2 "blocks: expected a list of 1 to 1024" "$QC" job e.json || return 1
    [ ! -e quilt.pat ] && [ -z "$(ls -A | grep -v json)" ]
}
check job_file_errors_name_the_key job_errors

# The job's guard checks what is sewn, the curves flattened: a pebbling block
# whose cubics' control points lie past the seam (curves inside) is written;
# a tiled block at margin 0, 2 mm past the edge, is refused with one line.
job_guard_checks_the_curve() {
    d=$(mktemp -d "$WORK/jobguard.XXXXXX") && cd "$d" || return 1
    echo '{"units": "in", "blocks": [{"region": "rect:8x8", "family": "pebbling",
        "params": {"spacing": 0.4}}]}' > peb.json
    "$QC" job -q peb.json -o peb.pat && "$QC" check peb.pat >/dev/null || return 1
    echo '{"blocks": [{"region": "rect:8x8", "params": {"tile": "edge-to-edge", "margin": 0}}]}' > out.json
    expect_fail 1 "job: blocks\[0\]: the stipple pattern reaches .* outside the region rect:8x8 (0..203.2, 0..203.2 mm); no file is written" \
        "$QC" job out.json -o out.pat || return 1
    [ ! -e out.pat ]
}
check job_guard_checks_the_flattened_curve job_guard_checks_the_curve

# Names in a job file (region and motif SVGs, point files, listed outputs)
# are relative to the job file, wherever quiltc runs; -o is relative to here.
job_relative_names() {
    d=$(mktemp -d "$WORK/jobrel.XXXXXX") && mkdir "$d/q" "$d/run" || return 1
    cp "$ROOT/tests/fixtures/svg/heart.svg" "$d/q/block.svg" &&
        printf '10,10\n30,12\n20,30\n' > "$d/q/pts.csv" &&
        "$QC" motifs --svg leaf > "$d/q/leaf.svg" || return 1
    cat > "$d/q/quilt.json" <<'JSON'
{"units": "mm", "output": ["quilt.pat"],
 "blocks": [{"region": "block.svg", "family": "branching", "motif": "leaf.svg,heart"},
            {"region": "rect:40x40", "at": [120, 0], "params": {"points": "pts.csv", "margin": 1}}]}
JSON
    (cd "$d/run" && "$QC" job ../q/quilt.json) && [ -s "$d/q/quilt.pat" ] &&
        [ -z "$(ls -A "$d/run")" ] && "$QC" check --max-jumps 1 "$d/q/quilt.pat" >/dev/null &&
        (cd "$d/run" && "$QC" job ../q/quilt.json -o here.pat) && [ -s "$d/run/here.pat" ]
}
check job_names_are_relative_to_the_job_file job_relative_names

# A job's jumps between tie-offs are thread cuts by design: check passes its
# own outputs (any format), while the same quilt without tie-offs, or a jump
# put into a file by hand, is still flagged.
job_jumps_designed() {
    "$QC" job "$ROOT/examples/quilt.json" -o quilt.pat -o quilt.qli &&
        "$QC" check quilt.pat > c.txt && grep -q 'thread cuts .*: 3$' c.txt &&
        "$QC" check quilt.qli > /dev/null || { cat c.txt; return 1; }
    sed 's/"tie": 3/"tie": 0/' "$ROOT/examples/quilt.json" > untied.json &&
        "$QC" job untied.json -o untied.pat || return 1
    "$QC" check untied.pat > u.txt
    [ $? -eq 1 ] && grep -q 'finding: 3 jumps .* without a tie-off' u.txt || { cat u.txt; return 1; }
    # one stray jump in the middle of the tied quilt: G00 on a stitched line
    awk 'NR == 200 { sub(/G01/, "G00") } { print }' quilt.pat > stray.pat
    "$QC" check stray.pat > s.txt
    [ $? -eq 1 ] && grep -q 'finding: 1 jumps' s.txt || { cat s.txt; return 1; }
}
check job_jumps_between_tie_offs_are_thread_cuts job_jumps_designed

# No stitch below the minimum right after a tie-off (meander seed 2 made one
# of 0.036 mm): check with the generator's own minimum passes.
tie_short_stitch() {
    "$QC" generate -q --family meander --region rect:3x3 --tie 3 --seed 2 -o m.pat &&
        "$QC" check --min-segment 0.4mm m.pat > m.txt || { grep finding m.txt | head -3; return 1; }
}
check no_short_stitch_after_a_tie_off tie_short_stitch

# quiltc check finds each kind of fault in deliberately broken files.
check_finds() { # FILE PATTERN: exit 1 and a line matching PATTERN
    "$QC" check "$ROOT/tests/bad/pat/$1" --region rect:8x8 --no-crossing > out.txt
    [ $? -eq 1 ] && grep -q -- "$2" out.txt && grep -q "not sewable" out.txt || { cat out.txt; return 1; }
}
check check_finds_numbering check_finds numbering.pat "N4 where N3 was expected"
check check_finds_decimals check_finds decimals.pat "X has 2 and Y 3 decimals"
check check_finds_lf_endings check_finds lf_endings.pat "expected CRLF"
check check_finds_unknown_command check_finds unknown_command.pat "unknown command 'G05"
check check_finds_missing_m02 check_finds missing_m02.pat "missing the final M02"
check check_finds_jumps check_finds jump.pat "1 jumps (needle-up moves) without a tie-off on both sides, more than 0"
check check_finds_short_stitch check_finds short_stitch.pat "segment of 0.051 mm shorter"
check check_finds_points_outside check_finds outside.pat "segments outside the region, up to"
check check_finds_self_crossing check_finds crossing.pat "1 self-crossings"
# a stitch whose ends are both in the block but which crosses its window
through_hole() {
    "$QC" check "$ROOT/tests/bad/pat/through_hole.pat" --units mm \
        --region "$ROOT/tests/fixtures/svg/block_with_hole.svg" > out.txt
    [ $? -eq 1 ] && grep -q "1 segments outside the region, up to 19.9" out.txt &&
        grep -q "farthest fabric from a stitch: 65.2 mm" out.txt || { cat out.txt; return 1; }
}
check check_finds_segments_through_a_hole through_hole
# check and --stats report the same farthest fabric
same_farthest() {
    "$QC" generate --family stipple --region star:6 --spacing 0.4 -o s.pat --stats 2> st.json &&
        "$QC" check s.pat --region star:6 > out.txt
    python3 -c '
import json, re, sys
s = json.loads(open("st.json").read().strip().splitlines()[-1])
m = re.search(r"farthest fabric from a stitch: ([0-9.]+) mm", open("out.txt").read())
assert m and abs(float(m.group(1)) - s["farthest_fabric_mm"]) < 0.6, (m and m.group(1), s)
' || { cat out.txt st.json; return 1; }
}
check check_and_stats_agree_on_the_farthest_fabric same_farthest
check check_finds_empty_file check_finds empty.pat "no stitches"

# Every format quiltc writes from a PAT reads back; a PAT round trip is exact.
convert_round_trip() {
    "$QC" generate -o a.pat --region circle:5 &&
        for ext in svg dxf plt qli qcc iqp bqm gcode pat; do "$QC" convert a.pat "b.$ext" || return 1; done &&
        cmp a.pat b.pat && "$QC" convert b.svg c.pat && "$QC" check c.pat >/dev/null
}
check convert_pat_to_every_format convert_round_trip

# quiltc's own SVG preview converts back to the same stitches at the same
# place (issue #19: the root's data-quiltc-origin-mm undoes the page margin):
# the block outline and the dashed jump lines are not sewn, every point and
# jump returns unshifted, within one PAT step (the preview keeps 0.0001 in,
# so a point can round the other way), in inches and in mm.
svg_preview_round_trip() {
    echo '{"tie": 0, "output": ["a.pat", "a.svg"], "blocks": [{"region": "rect:4x4"},
        {"region": "circle:3", "at": [5, 0.5]}]}' > two.json &&
        "$QC" job two.json && "$QC" convert a.svg b.pat &&
        "$QC" generate -q --units mm --region rect:150x120 -o c.pat -o c.svg &&
        "$QC" convert c.svg d.pat && python3 - a.pat b.pat c.pat d.pat <<'PY'
import re, sys
def read(f):
    return re.findall(r'N\d+(G0[01])X([\d.]+)Y([\d.]+)', open(f).read())
for fa, fb, jumps in ((sys.argv[1], sys.argv[2], 2), (sys.argv[3], sys.argv[4], None)):
    a, b = read(fa), read(fb)
    assert len(a) == len(b), (fa, len(a), len(b))
    assert jumps is None or sum(c == 'G00' for c, _, _ in a) == jumps, 'expected two jumps'
    same = 0
    for (ca, xa, ya), (cb, xb, yb) in zip(a, b):
        assert ca == cb, (ca, cb)
        assert abs(float(xb) - float(xa)) < 0.0011 and abs(float(yb) - float(ya)) < 0.0011, (xa, ya, xb, yb)
        same += (xa, ya) == (xb, yb)
    assert same >= 0.95 * len(a), (fa, same, len(a))
PY
}
check svg_preview_converts_back_to_the_same_stitches svg_preview_round_trip

# An Inkscape-style file: the clone is read as drawn, and what the reader
# cannot honour is one warning line each on stderr (the pattern is still
# written), from generate and from convert alike.
svg_warnings_are_one_line_each() {
    printf '%s' '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><defs><rect id="r" width="80" height="80"/></defs><use href="#r" x="10" y="10" clip-path="url(#c)"/><text>hi</text></svg>' > w.svg &&
        "$QC" generate -q --region w.svg --units mm -o w.pat 2> err.txt && [ -s w.pat ] &&
        [ "$(wc -l < err.txt)" -eq 2 ] &&
        grep -q "w.svg: warning: svg line 1, <use> (element 4): clip-path url(#c) is not applied" err.txt &&
        grep -q "w.svg: warning: svg line 1, <text> (element 5): text is not read" err.txt &&
        "$QC" convert -q w.svg w2.pat 2> err2.txt && [ "$(wc -l < err2.txt)" -eq 2 ] &&
        grep -q "N2G01X3.543Y3.543" w2.pat || { cat err.txt err2.txt; head -3 w2.pat; return 1; }
}
check svg_warnings_are_one_line_each svg_warnings_are_one_line_each

# Errors: the status, one stderr line naming the value, and no file left behind.
fails_cleanly() {
    d=$(mktemp -d "$WORK/err.XXXXXX") && cd "$d" || return 1
    expect_fail "$@" || return 1
    [ -z "$(ls -A)" ] || { echo "left behind: $(ls -A)"; return 1; }
}
check spacing_out_of_range fails_cleanly 2 "spacing 0 in (0 mm) out of range \[0.01969, 39.37\] in" "$QC" generate --spacing 0
check spacing_nan fails_cleanly 2 "'nan' is not a length" "$QC" generate --spacing nan
check unknown_shape fails_cleanly 2 "unknown shape 'blob:3'" "$QC" generate --region blob:3
check negative_size fails_cleanly 2 "size -2 mm" "$QC" generate --region circle:-2 --units mm
check unknown_units fails_cleanly 2 "unknown unit 'furlong'" "$QC" generate --units furlong
check unknown_family fails_cleanly 2 "unknown choice 'plaid'" "$QC" generate --family plaid
check bad_seed fails_cleanly 2 "'-1' is not a whole number" "$QC" generate --seed -1
check unknown_format fails_cleanly 2 "'x.doc': unknown format" "$QC" generate -o x.doc
check stdout_needs_format fails_cleanly 2 "give --format" "$QC" generate -o -
check unknown_option fails_cleanly 2 "unknown option '--bogus'" "$QC" generate --bogus
check stray_argument fails_cleanly 2 "unexpected argument 'extra'" "$QC" generate extra
check unknown_command fails_cleanly 2 "unknown command 'sew'" "$QC" sew
check too_many_points fails_cleanly 1 "exceed the limit" "$QC" generate --region rect:1000x1000 --spacing 0.5mm
check missing_svg fails_cleanly 1 "cannot open 'nope.svg'" "$QC" generate --region nope.svg
check self_intersecting_svg fails_cleanly 1 "crosses itself" "$QC" generate --region "$ROOT/tests/bad/svg/bowtie.svg"
check unwritable_output fails_cleanly 1 "no/such/dir/p.pat" "$QC" generate -o no/such/dir/p.pat

# A failure after the first output leaves no output at all.
all_or_nothing() {
    d=$(mktemp -d "$WORK/aon.XXXXXX") && cd "$d" || return 1
    expect_fail 1 "no/dir/x.svg" "$QC" generate -o ok.pat -o no/dir/x.svg &&
        [ -z "$(ls -A)" ] || { echo "left behind: $(ls -A)"; return 1; }
    echo '{"blocks": [{"region": "rect:2x2"}]}' > j.json &&
        expect_fail 1 "no/dir/q.svg" "$QC" job j.json -o ok.pat -o no/dir/q.svg &&
        [ "$(ls -A)" = j.json ] || { echo "job left behind: $(ls -A)"; return 1; }
}
check several_outputs_all_or_nothing all_or_nothing

# -o never replaces what it names: a symbolic link keeps pointing at the
# file it names, which gets the pattern; a FIFO stays a FIFO and its reader
# gets the pattern; /dev/null takes it.
special_outputs() {
    d=$(mktemp -d "$WORK/special.XXXXXX") && cd "$d" || return 1
    "$QC" generate -o want.pat --seed 3 || return 1
    mkdir real && echo old > real/p.pat && ln -s real/p.pat link.pat &&
        "$QC" generate -o link.pat --seed 3 && [ -L link.pat ] && cmp want.pat real/p.pat &&
        [ -z "$(ls real | grep -v '^p.pat$')" ] || { echo "symlink: $(ls -l . real)"; return 1; }
    mkfifo fifo.pat && { cat fifo.pat > got.pat & } &&
        "$QC" generate -o fifo.pat --seed 3 && wait && [ -p fifo.pat ] && cmp want.pat got.pat ||
        { echo "fifo: $(ls -l)"; return 1; }
    "$QC" generate -o /dev/null --format pat && [ -c /dev/null ] || return 1
    ln -s missing.pat dangling.pat &&
        expect_fail 1 "'dangling.pat': symbolic link to a missing file" "$QC" generate -o dangling.pat
}
check output_to_symlink_fifo_or_device_keeps_it special_outputs

finish
