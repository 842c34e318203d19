#!/bin/sh
# quiltc quilt end to end: a pieced top sewn as one line, a plan choosing
# families, --join jump, and every bad plan or top refused in one line
# with no file written.
. tests/cli_lib.sh
ROOT=$(pwd)
NINE=$ROOT/tests/data/quilt/nine-patch.svg
STAR=$ROOT/examples/sawtooth-star.svg

# G00 lines of a .pat: the pieces (the first line always is one).
pieces() { grep -c 'G00' "$1"; }

one_line() {
    "$QC" quilt "$NINE" && [ "$(pieces quilt.pat)" -eq 1 ] && grep -q 'id="ditch"' quilt.svg &&
        grep -q 'id="region"' quilt.svg && "$QC" check quilt.pat >/dev/null &&
        "$QC" check quilt.pat --region "$NINE" --units in >/dev/null
}
check nine_patch_is_one_line_with_outlines_and_ditch one_line

# Every real top: one line whose points and stitched segments all lie in its
# patches or on their seams, as quiltc check measures them.
every_top() {
    for t in "$STAR" "$ROOT"/tests/data/quilt/*.svg; do
        "$QC" quilt "$t" -o t.pat && [ "$(pieces t.pat)" -eq 1 ] &&
            "$QC" check t.pat --region "$t" >out.txt || { cat out.txt; echo "$t"; return 1; }
    done
}
check every_top_is_one_line_inside_its_patches every_top

# The written .pat crosses itself nowhere for the families that never cross
# (check counts proper crossings of its stitches): the stitch plan keeps
# the corner where a pebble's link meets a seam 0.5 mm away (it merged it
# away, and one stitch cut across the pebble: 11 on log-cabin, 30 on the
# sashing top), and a spiral winds back out to the seam (its link out from
# the centre crossed 8 of its turns on the star).
no_crossings() {
    for f in pebbling spiral echo vine stipple; do
        for t in "$STAR" "$ROOT"/tests/data/quilt/log-cabin.svg "$ROOT"/tests/data/quilt/sashing.svg; do
            "$QC" quilt "$t" --family $f -q -o x.pat &&
                "$QC" check x.pat --region "$t" --no-crossing >out.txt ||
                { grep -E 'crossing|finding' out.txt | head -3; echo "$f $t"; return 1; }
        done
    done
    rm -f x.pat # the refusals below check that no file is written
}
check written_pat_never_crosses_itself no_crossings

# A patch too small for the spacing is sewn round in the ditch, said once.
tiny_patches() {
    "$QC" quilt "$ROOT/tests/data/quilt/tiny-patches.svg" -o t.pat --stats 2>err.txt &&
        [ "$(pieces t.pat)" -eq 1 ] && [ "$(grep -c 'too small for stipple' err.txt)" -eq 2 ] &&
        grep -q 'id "tiny" (line 3) is too small for stipple at spacing 0.5 in' err.txt &&
        grep '^{' err.txt >stats.json && python3 -c '
import json
s = json.load(open("stats.json"))
d = {p["id"]: p.get("ditch_only", False) for p in s["patches"]}
assert d == {"big": False, "tiny": True, "strip": True}, d
assert s["quilted"] == 3 and s["jumps"] == 0, s
' && "$QC" check t.pat --region "$ROOT/tests/data/quilt/tiny-patches.svg" >/dev/null
}
check patch_too_small_is_sewn_round_in_the_ditch tiny_patches

# Edges drawn 0.04 mm apart are one seam by default; --seam-gap says how far.
seam_gap() {
    printf '%s' "<svg xmlns='http://www.w3.org/2000/svg' width='200mm' height='100mm' viewBox='0 0 200 100'><rect x='0' y='0' width='100' height='100'/><rect x='100.04' y='0.03' width='99.96' height='99.97'/></svg>" >gap.svg &&
        "$QC" quilt gap.svg -o g1.pat && [ "$(pieces g1.pat)" -eq 1 ] &&
        "$QC" quilt gap.svg -o g2.pat --seam-gap 0.01mm && [ "$(pieces g2.pat)" -eq 2 ] &&
        expect_fail 2 '^quiltc: --seam-gap 1 in (25.4 mm) out of range \[0, 0.3937\] in$' \
            "$QC" quilt gap.svg -o g3.pat --seam-gap 1 && [ ! -e g3.pat ] &&
        expect_fail 2 "^quiltc: --seam-gap: 'x' is not a length$" "$QC" quilt gap.svg -o g3.pat --seam-gap x
}
check seam_gap_joins_edges_drawn_slightly_apart seam_gap

# check against a top gives every patch's own figures, by id.
check_per_patch() {
    "$QC" quilt "$STAR" --plan "$ROOT/examples/sawtooth-star.json" -o pp.pat &&
        "$QC" check pp.pat --region "$STAR" --units in >out.txt &&
        [ "$(grep -c '^patch [0-9]* (id "[a-z-]*"): farthest fabric [0-9.]* mm ([0-9.]* in), largest gap [0-9.]* mm radius$' out.txt)" -eq 17 ] &&
        grep -q '^patch 1 (id "centre"): ' out.txt && python3 -c '
import re
v = [float(m) for m in re.findall(r"farthest fabric (?:from a stitch: )?([0-9.]+) mm", open("out.txt").read())]
assert len(v) == 18 and abs(v[0] - max(v[1:])) <= 0.6, v  # the top is its farthest patch, within a 0.5 mm cell
'
}
check check_gives_each_patch_its_figures check_per_patch

plan_families() {
    "$QC" quilt "$STAR" --plan "$ROOT/examples/sawtooth-star.json" -o star.pat --stats \
        2>stats.json && [ "$(pieces star.pat)" -eq 1 ] && python3 -c '
import json
s = json.load(open("stats.json"))
want = {"centre": ("rules[0]", "pebbling")}
for p in s["patches"]:
    if p["id"] == "centre": assert (p["rule"], p["family"]) == ("rules[0]", "pebbling"), p
    elif p["id"].startswith("point-"): assert (p["rule"], p["family"]) == ("rules[1]", "echo"), p
    elif p["id"].startswith("goose-"): assert (p["rule"], p["family"]) == ("rules[2]", "stipple"), p
    else: assert (p["rule"], p["family"]) == ("rules[3]", "spiral"), p
    assert p["length_mm"] > 0 and p["order"] >= 1, p
assert s["quilted"] == 17 and s["unquilted"] == 0 and s["jumps"] == 0 and s["pieces"] == 1, s
assert s["ditch_mm"] > 0 and s["sewn_mm"] > s["pattern_mm"], s
'
}
check plan_rules_choose_each_patch_family plan_families

dxf_outlines() {
    "$QC" quilt "$NINE" -o q.dxf && python3 -c '
lines = open("q.dxf").read().split("\n")
pairs = [(lines[i].strip(), lines[i + 1].strip()) for i in range(0, len(lines) - 1, 2)]
layers = [pairs[i + 1][1] for i, p in enumerate(pairs) if p == ("0", "POLYLINE")]
assert layers.count("OUTLINES") == 9 and layers.count("0") == 1, layers
'
}
check dxf_has_the_outlines_on_their_own_layer dxf_outlines

none_rule() {
    printf '[{"match": {"fill": "#F5F0E1"}, "family": "none"}, {"family": "echo"}]' >p.json &&
        "$QC" quilt "$NINE" --plan p.json -o n.pat --stats 2>stats.json && python3 -c '
import json
s = json.load(open("stats.json"))
assert s["quilted"] == 5 and s["unquilted"] == 4 and s["pieces"] == 1, s
assert all(p["family"] == ("echo" if p["id"] in ("p00", "p02", "p11", "p20", "p22") else "none")
           for p in s["patches"]), s
'
}
check family_none_leaves_light_patches_unquilted none_rule

same_bytes() {
    "$QC" quilt "$STAR" -o a.pat --seed 5 && "$QC" quilt "$STAR" -o b.pat --seed 5 &&
        cmp a.pat b.pat && "$QC" quilt "$STAR" -o c.pat --seed 6 && ! cmp -s a.pat c.pat
}
check same_seed_same_bytes same_bytes

jump_join() {
    "$QC" quilt "$NINE" --join jump -o j.pat --tie 0 && [ "$(pieces j.pat)" -eq 9 ]
}
check join_jump_starts_a_piece_per_patch jump_join

# A bad plan or top: one line naming the key, exit 2, no file.
refused() {
    pattern=$1
    shift
    expect_fail 2 "$pattern" "$QC" quilt "$@" -o x.pat -o x.svg && [ ! -e x.pat ] && [ ! -e x.svg ]
}

plan_case() {
    printf '%s' "$1" >bad.json
    refused "$2" "$NINE" --plan bad.json
}
check plan_unknown_key plan_case '[{"family": "echo", "colour": "red"}]' 'rules\[0\]\.colour: unknown key'
check plan_unknown_match_key plan_case '[{"match": {"ID": "p*"}}]' 'rules\[0\]\.match\.ID: unknown key'
check plan_bad_colour plan_case '[{"match": {"fill": "#12345"}}]' "rules\[0\]\.match\.fill: '#12345' is not a colour"
check plan_rule_matching_nothing plan_case '[{"match": {"id": "star-*"}, "family": "echo"}, {"family": "stipple"}]' 'rules\[0\] matches no patch'
check plan_unknown_family plan_case '[{"family": "quilting"}]' 'rules\[0\]\.family: unknown choice'
check plan_bad_parameter plan_case '[{"params": {"spacing": -1}}]' 'rules\[0\].params.spacing -1 in (-25.4 mm) out of range'
check plan_wrong_type plan_case '[{"match": {"class": 3}}]' 'rules\[0\]\.match\.class: expected a string'
check plan_not_a_list plan_case '{"rules": []}' 'plan: rules: expected a list'
check plan_malformed_json plan_case '[{"family": }]' 'malformed JSON at byte'

overlap() {
    printf '%s\n' '<svg xmlns="http://www.w3.org/2000/svg" width="10in" height="10in" viewBox="0 0 10 10">' \
        '<rect id="left" x="0" y="0" width="6" height="4"/>' \
        '<rect id="right" x="5" y="0" width="5" height="4"/></svg>' >o.svg &&
        refused 'patches id "left" (line 2) and id "right" (line 3) overlap near ([0-9.]*, [0-9.]*) in' o.svg
}
check overlapping_patches_name_both overlap

two_squares() {
    printf '%s\n' '<svg xmlns="http://www.w3.org/2000/svg" width="10in" height="4in" viewBox="0 0 10 4">' \
        '<rect x="0" y="0" width="4" height="4"/><rect x="6" y="0" width="4" height="4"/></svg>' >two.svg
}

pieces_jump() {
    two_squares && "$QC" generate --region two.svg -o two.pat && [ "$(pieces two.pat)" -eq 2 ] &&
        "$QC" check two.pat --region two.svg --max-jumps 1 >out.txt && ! grep -q 'leave' out.txt
}
check generate_sews_separate_pieces_joined_by_a_jump pieces_jump

gap_segment() {
    two_squares && printf 'N1G00X1.000Y1.000\r\nN2G01X9.000Y1.000\r\nN3M02\r\n' >gap.pat &&
        ! "$QC" check gap.pat --region two.svg >out.txt && grep -q '1 segments outside the region' out.txt
}
check check_flags_a_segment_across_the_gap gap_segment

# Fix on the way: a job block stays where "at" puts it (the box of the
# flattened path, not of its control points, decides the shift).
job_in_place() {
    printf '{"units": "in", "blocks": [{"region": "rect:4x4", "at": [4, 0], "family": "stipple"}]}' >j.json &&
        "$QC" job j.json -o j.pat && "$QC" check j.pat >out.txt &&
        python3 -c '
import re
b = [float(v) for v in re.search(r"bbox: (\S+) (\S+) (\S+) (\S+) in", open("out.txt").read()).groups()]
assert 4.0 < b[0] and 0.0 < b[1] and b[2] < 8.0 and b[3] < 4.0, b
assert b[1] < 0.2 and b[3] > 3.8, b
'
}
check job_block_stays_at_its_place job_in_place

job_overlap() {
    printf '{"blocks": [{"region": "rect:8x8", "at": [0, 0]}, {"region": "circle:6", "at": [7, 1]}]}' >ov.json &&
        expect_fail 2 'job: blocks\[0\] and blocks\[1\] overlap near ([0-9.]*, [0-9.]*) in' "$QC" job ov.json -o ov.pat &&
        [ ! -e ov.pat ] && "$QC" job "$ROOT/examples/quilt.json" -o ok.pat
}
check job_blocks_that_overlap_are_refused job_overlap

job_top() {
    cp "$STAR" star.svg &&
        printf '%s' '{"units": "in", "blocks": [{"top": "star.svg", "at": [0, 0], "plan": [{"match": {"class": "point"}, "family": "echo"}, {"family": "stipple"}]}, {"region": "rect:12x12", "at": [12, 0], "family": "stipple"}]}' >t.json &&
        "$QC" job t.json -o t.pat && [ "$(pieces t.pat)" -eq 2 ] && "$QC" check t.pat --max-jumps 1 >out.txt &&
        python3 -c '
import re
b = [float(v) for v in re.search(r"bbox: (\S+) (\S+) (\S+) (\S+) in", open("out.txt").read()).groups()]
assert b[0] < 0.5 and b[2] > 23.5 and b[2] < 24 and b[3] < 12, b
'
}
check job_mixes_a_pieced_top_with_a_block job_top

# A top's plan names its motif files beside the job, as a block does, and
# may not reach outside the job's folder.
job_top_plan_motif() {
    mkdir -p q && cp "$STAR" q/star.svg && "$QC" motifs --svg leaf >q/leaf.svg &&
        printf '%s' '{"blocks": [{"top": "star.svg", "plan": [{"match": {"id": "centre"}, "family": "branching", "motif": "leaf.svg"}, {"family": "stipple"}]}]}' >q/t.json &&
        "$QC" job q/t.json -o tm.pat && [ "$(pieces tm.pat)" -eq 1 ] &&
        printf '%s' '{"blocks": [{"top": "star.svg", "plan": [{"family": "branching", "motif": "../leaf.svg"}]}]}' >q/out.json &&
        expect_fail 2 'job: blocks\[0\]\.plan\[0\]\.motif' "$QC" job q/out.json -o to.pat && [ ! -e to.pat ]
}
check job_top_plan_motifs_are_beside_the_job job_top_plan_motif

job_top_bad_plan() {
    cp "$STAR" star.svg && printf '%s' '{"blocks": [{"top": "star.svg", "plan": [{"colour": "red"}]}]}' >b.json &&
        expect_fail 2 'job: blocks\[0\]\.plan\[0\]\.colour: unknown key' "$QC" job b.json -o bj.pat && [ ! -e bj.pat ]
}
check job_top_plan_errors_name_the_key job_top_bad_plan

check region_option_refused refused 'not --region' "$NINE" --region rect:8x8
check bad_join_refused refused "--join: 'seam' is neither ditch nor jump" "$NINE" --join seam
check missing_top_refused refused 'expected a TOP.svg' --spacing 0.5

finish
