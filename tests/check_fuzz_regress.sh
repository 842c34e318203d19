#!/bin/sh
# Replays the fuzz corpus (tests/fuzz/corpus/<target>/) and every
# regression input (tests/fuzz/regress/<target>/) through the fuzz targets
# built with a plain main ($BUILD/fuzz-replay/fuzz_<target>, made by
# `make test`; under SAN=1 with ASan and UBSan): no crash, no broken
# invariant, no leak. One case per target's corpus and one per regression
# input; inputs of open findings (tests/fuzz/known.txt) are Ignored, and
# the corpus is replayed stepping around them (QC_FUZZ_KNOWN), as the
# fuzzer that grew it did.
BUILD=${BUILD:-build}
KNOWN=$(grep -v '^#' tests/fuzz/known.txt 2>/dev/null | cut -d'|' -f2 | sort -u | tr '\n' ',')
run=0 fail=0 ign=0
log=$(mktemp) || exit 1
trap 'rm -f "$log"' EXIT

case_ok() { run=$((run + 1)); echo "$0:$run:$1:PASS"; }
case_fail() {
    run=$((run + 1)); fail=$((fail + 1))
    echo "$0:$run:$1:FAIL: $(grep -m 2 -E 'invariant|ERROR|runtime error|Abort|Segmentation' "$log" | tr '\n' ' ')"
}
case_ignored() { run=$((run + 1)); ign=$((ign + 1)); echo "$0:$run:$1:IGNORE: $2"; }

for dir in tests/fuzz/corpus/*/; do
    t=$(basename "$dir")
    bin=$BUILD/fuzz-replay/fuzz_$t
    if [ ! -x "$bin" ]; then
        run=$((run + 1)); fail=$((fail + 1))
        echo "$0:$run:fuzz_${t}_corpus:FAIL: $bin not built (make test builds it)"
        continue
    fi
    if QC_FUZZ_KNOWN=$KNOWN "$bin" "$dir" >"$log" 2>&1; then
        case_ok "fuzz_${t}_corpus_$(ls "$dir" | wc -l | tr -d ' ')_inputs"
    else
        case_fail "fuzz_${t}_corpus"
    fi
    [ -d "tests/fuzz/regress/$t" ] || continue
    for f in tests/fuzz/regress/"$t"/*; do
        [ -f "$f" ] || continue
        name=$t/$(basename "$f")
        known=$(grep -F "$name|" tests/fuzz/known.txt 2>/dev/null | cut -d'|' -f3)
        if [ -n "$known" ]; then
            case_ignored "regress_$name" "open finding: $known"
        elif env -u QC_FUZZ_KNOWN "$bin" "$f" >"$log" 2>&1; then
            case_ok "regress_$name"
        else
            case_fail "regress_$name"
        fi
    done
done
printf '\n-----------------------\n%d Tests %d Failures %d Ignored\n' "$run" "$fail" "$ign"
[ "$fail" -eq 0 ] && echo OK || echo FAIL
[ "$fail" -eq 0 ]
