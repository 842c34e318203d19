#!/bin/sh
# run_fuzz.sh SECONDS TARGET...: runs build-fuzz/fuzz_TARGET for SECONDS on
# a fresh copy of tests/fuzz/corpus/TARGET (new inputs go into the copy, not
# the repository) plus tests/fuzz/regress/TARGET, with the target's
# dictionary when it has one. One summary line per target; exits non-zero
# when any target found something (the input is in
# $FUZZ_BUILD/artifacts/TARGET/, the log in $FUZZ_BUILD/logs/TARGET.log).
# Extra libFuzzer flags: FUZZ_FLAGS="-seed=1 ...". The open findings listed
# in tests/fuzz/known.txt are stepped around (QC_FUZZ_KNOWN) unless
# QC_FUZZ_STRICT=1, so a run looks for new ones.
B=${FUZZ_BUILD:-build-fuzz}
if [ "${QC_FUZZ_STRICT:-0}" != 1 ] && [ -f tests/fuzz/known.txt ]; then
    QC_FUZZ_KNOWN=$(grep -v '^#' tests/fuzz/known.txt | cut -d'|' -f2 | sort -u | tr '\n' ',')
    export QC_FUZZ_KNOWN
fi
secs=${1:-60}
shift
status=0
for t in "$@"; do
    bin=$B/fuzz_$t
    [ -x "$bin" ] || { echo "fuzz_$t: not built"; status=1; continue; }
    rm -rf "$B/corpus/$t" "$B/artifacts/$t"
    mkdir -p "$B/corpus/$t" "$B/artifacts/$t" "$B/logs"
    cp tests/fuzz/corpus/"$t"/* "$B/corpus/$t/" 2>/dev/null
    set -- -max_total_time="$secs" -timeout=20 -rss_limit_mb=2560 -print_final_stats=1 \
        -artifact_prefix="$B/artifacts/$t/"
    case $t in
        svg_region) set -- "$@" -max_len=16384 ;;
        motif) set -- "$@" -max_len=8192 ;;
        pat|points|read) set -- "$@" -max_len=8192 ;;
        generate) set -- "$@" -max_len=512 ;;
        job) set -- "$@" -max_len=4096 -close_fd_mask=2 ;;
    esac
    [ -f "tests/fuzz/$t.dict" ] && set -- "$@" -dict="tests/fuzz/$t.dict"
    regress=
    [ -d "tests/fuzz/regress/$t" ] && regress="tests/fuzz/regress/$t"
    # shellcheck disable=SC2086
    "$bin" "$@" $FUZZ_FLAGS "$B/corpus/$t" $regress >"$B/logs/$t.log" 2>&1
    rc=$?
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$B/logs/$t.log" | tail -n 1)
    found=$(ls "$B/artifacts/$t" | wc -l)
    echo "fuzz_$t: ${runs:-?} executions in ${secs} s, corpus $(ls "$B/corpus/$t" | wc -l) inputs, exit $rc, $found finding(s)"
    if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
        status=1
        grep -m 1 -E 'ERROR|runtime error|invariant|Timeout|leak' "$B/logs/$t.log"
        ls "$B/artifacts/$t"
    fi
done
exit $status
