#!/bin/sh
# --tsp concorde: against stand-ins that misbehave (a tour that is not a
# permutation, a hang that ignores SIGTERM, a failed exit), then against the
# real solver when it is built (.ci/run builds it into build/concorde from
# ../shared/tools/concorde): the proven optima of berlin52, a280 and pr1002,
# and a wanderer on its tour. Concorde's files never leak into the current
# folder or TMPDIR.
. tests/cli_lib.sh
ROOT=$(pwd)
REAL=${QUILTC_CONCORDE_DIR:-$ROOT/build/concorde}
T_SKIP=0

# A stand-in concorde in folder $1 running shell code $2 ($SOL: its -o file).
fake() {
    mkdir -p "$1"
    cat >"$1/concorde" <<EOF
#!/bin/sh
SOL=
while [ \$# -gt 1 ]; do [ "\$1" = -o ] && SOL=\$2; [ "\$1" = -x ] && exit 9; shift; done
N=\$(sed -n 's/^DIMENSION: //p' in.tsp)
$2
EOF
    chmod +x "$1/concorde"
}

# Nothing of concorde's left in the current folder or in TMPDIR.
no_leak() {
    [ -z "$(ls "$WORK/tmp")" ] || { echo "left in TMPDIR: $(ls "$WORK/tmp")"; return 1; }
    ! ls ./*.sol ./*.sav ./*.pul ./*.mas ./*.tsp 2>/dev/null | grep -q . || { echo "left here: $(ls)"; return 1; }
}

SKEL="skeleton --region square:100 --units mm --points square --spacing 10 --path tsp --tsp concorde"

# The stand-in writes its files where it runs, as concorde does, and the
# identity tour: accepted, and its files are gone (PATH relative, as a
# user may have it: concorde runs elsewhere).
fake_tour_used() {
    fake f 'echo x > in.sol; echo x > Oin.sav; { echo "$N"; seq 0 $((N - 1)); } > "$SOL"; exit 0'
    mkdir -p tmp && TMPDIR=$WORK/tmp PATH=f:$PATH "$QC" $SKEL -o s.json &&
        python3 -c '
import json
s = json.load(open("s.json"))
assert sorted(s["order"]) == list(range(len(s["points"]))) and len(s["points"]) > 50, s
' && no_leak
}
check fake_concorde_tour_used_and_its_files_removed fake_tour_used

not_permutation() {
    fake f '{ echo "$N"; seq 0 $((N - 2)); echo 0; } > "$SOL"; exit 0'
    mkdir -p tmp && TMPDIR=$WORK/tmp PATH=$WORK/f:$PATH expect_fail 1 \
        "concorde's tour is not a permutation of the" "$QC" $SKEL -o np.json &&
        [ ! -e np.json ] && no_leak
}
check tour_that_is_not_a_permutation_refused not_permutation

# The -x bug's way: a tour, then exit 255. Only exit 0 is trusted.
failed_exit() {
    fake f '{ echo "$N"; seq 0 $((N - 1)); } > "$SOL"; exit 255'
    mkdir -p tmp && TMPDIR=$WORK/tmp PATH=$WORK/f:$PATH expect_fail 1 \
        "concorde failed on" "$QC" $SKEL -o fe.json && [ ! -e fe.json ] && no_leak
}
check failed_exit_refused failed_exit

# Process $1 ends within 2 s (a killed orphan may linger a moment as a zombie).
gone() {
    i=0
    while kill -0 "$1" 2>/dev/null; do
        [ $i -ge 20 ] && { echo "process $1 still runs"; return 1; }
        sleep 0.1
        i=$((i + 1))
    done
}

# A hang that ignores SIGTERM (as concorde's crash handler sleeps an hour),
# with a child of its own: stopped at the limit, group and all.
timeout_kills() {
    fake f 'echo $$ > "$WORK_OUT/pid"; trap "" TERM; sleep 60 & echo $! > "$WORK_OUT/child"; wait; sleep 60'
    mkdir -p tmp && t0=$(date +%s) &&
        WORK_OUT=$WORK TMPDIR=$WORK/tmp PATH=$WORK/f:$PATH expect_fail 1 \
            "no tour from concorde within 0.3 s on" "$QC" $SKEL --tsp-time 300 -o to.json &&
        [ $(($(date +%s) - t0)) -lt 10 ] && [ ! -e to.json ] && no_leak &&
        gone "$(cat pid)" && gone "$(cat child)"
}
export WORK
check timeout_stops_concorde_and_its_children timeout_kills

# quiltc stopped by SIGTERM while concorde runs: concorde (a group of its
# own, out of reach of the terminal's signals) is stopped too, its folder
# removed, and quiltc dies of the signal.
stopped_by_signal() {
    fake f 'echo $$ > "$WORK_OUT/spid"; sleep 60 & echo $! > "$WORK_OUT/schild"; wait'
    mkdir -p tmp && rm -f spid &&
        { WORK_OUT=$WORK TMPDIR=$WORK/tmp PATH=$WORK/f:$PATH "$QC" $SKEL -o sg.json & } &&
        qpid=$! && i=0 && while [ ! -s spid ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done &&
        kill -TERM $qpid && { wait $qpid; st=$?; [ $st -eq 143 ] || { echo "status $st"; false; }; } &&
        gone "$(cat spid)" && gone "$(cat schild)" && [ ! -e sg.json ] && no_leak
}
check stopped_quiltc_stops_concorde stopped_by_signal

family_without_tour() {
    fake f 'exit 1'
    PATH=$WORK/f:$PATH expect_fail 2 "the branching family walks a tree, not a tour" \
        "$QC" generate --family branching --tsp concorde -o a.pat && [ ! -e a.pat ]
}
check tree_families_refuse_concorde family_without_tour

# ---- the real solver ----
tsplib() { # the instance's path, or nothing
    for d in "$ROOT/tests/data/tsplib" "$ROOT/../shared/data/tsplib"; do
        [ -f "$d/$1.tsp" ] && { echo "$d/$1.tsp"; return; }
    done
}

# The tour of --tsp concorde on instance $1 in a block of side $2 has the
# TSPLIB length $3 (nint of each edge), the proven optimum.
optimal() {
    f=$(tsplib "$1")
    mkdir -p tmp && TMPDIR=$WORK/tmp PATH=$REAL:$PATH "$QC" skeleton --points "$f" --units mm \
        --region "rect:$2x$2" --path tsp --tsp concorde -o t.json && no_leak &&
        python3 - "$f" "$3" <<'PY'
import json, math, sys
xy = []
sec = False
for line in open(sys.argv[1]):
    t = line.split()
    if t and t[0] == 'NODE_COORD_SECTION':
        sec = True
    elif t and t[0] == 'EOF':
        break
    elif sec and len(t) >= 3:
        xy.append((float(t[1]), float(t[2])))
o = json.load(open('t.json'))['order']
assert sorted(o) == list(range(len(xy))), 'not a tour'
L = sum(int(math.sqrt((xy[a][0] - xy[b][0]) ** 2 + (xy[a][1] - xy[b][1]) ** 2) + 0.5)
        for a, b in zip(o, o[1:] + o[:1]))
assert L == int(sys.argv[2]), 'length %d, optimum %s' % (L, sys.argv[2])
PY
}

wanderer_on_concorde() {
    mkdir -p tmp && TMPDIR=$WORK/tmp PATH=$REAL:$PATH "$QC" generate --family wanderer \
        --region square:150 --units mm --spacing 15 --tsp concorde --stats -o w.pat 2>st.json &&
        "$QC" check w.pat >/dev/null && no_leak &&
        "$QC" generate --family wanderer --region square:150 --units mm --spacing 15 -o b.pat &&
        ! cmp -s w.pat b.pat && grep -q '"order":' st.json &&
        TMPDIR=$WORK/tmp PATH=$REAL:$PATH "$QC" generate --family wanderer --region heart:150 \
            --units mm --spacing 15 --tsp concorde --stats -o h.pat 2>hs.json &&
        grep -q '"farthest_fabric_mm":[1-9]' hs.json && # measured, as every run is
        "$QC" check h.pat --region heart:150 --units mm >hc.txt && ! grep -q outside hc.txt
}

if [ -x "$REAL/concorde" ]; then
    check berlin52_optimal_7542 optimal berlin52 2000 7542
    check a280_optimal_2579 optimal a280 400 2579
    if [ -n "$(tsplib pr1002)" ]; then
        check pr1002_optimal_259045 optimal pr1002 20000 259045
    else
        echo "$0: SKIPPED pr1002: no pr1002.tsp in tests/data/tsplib or ../shared/data/tsplib"
        T_SKIP=$((T_SKIP + 1))
    fi
    check wanderer_tours_by_concorde wanderer_on_concorde
else
    echo "$0: SKIPPED the real-solver cases: no $REAL/concorde (build it: bash ../shared/tools/concorde/build.sh build/concorde)"
    T_SKIP=$((T_SKIP + 4))
fi
T_RUN=$((T_RUN + T_SKIP))
printf '\n-----------------------\n%d Tests %d Failures %d Ignored\n' "$T_RUN" "$T_FAIL" "$T_SKIP"
[ "$T_FAIL" -eq 0 ] && echo OK || echo FAIL
