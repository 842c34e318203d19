# Shared by tests/check_*.sh: tiny assertions that print Unity-style lines
# and the summary tests/run_tests.sh reads. Source it, call `check NAME CMD...`
# per case (CMD fails the case by returning non-zero), then `finish`.
QC=${QC:-$(pwd)/${BUILD:-build}/quiltc}
T_RUN=0 T_FAIL=0
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

check() {
    name=$1
    shift
    T_RUN=$((T_RUN + 1))
    if ( cd "$WORK" && "$@" ) >"$WORK/.log" 2>&1; then
        echo "$0:$T_RUN:$name:PASS"
    else
        T_FAIL=$((T_FAIL + 1))
        echo "$0:$T_RUN:$name:FAIL: $(tail -n 3 "$WORK/.log" | tr '\n' ' ')"
    fi
}

finish() {
    printf '\n-----------------------\n%d Tests %d Failures 0 Ignored\n' "$T_RUN" "$T_FAIL"
    [ "$T_FAIL" -eq 0 ] && echo OK || echo FAIL
}

# expect_fail STATUS PATTERN CMD...: CMD exits with STATUS and prints one
# stderr line matching PATTERN.
expect_fail() {
    want=$1 pattern=$2
    shift 2
    "$@" >"$WORK/.out" 2>"$WORK/.err"
    got=$?
    if [ "$got" -ne "$want" ]; then echo "exit $got, wanted $want: $(cat "$WORK/.err")"; return 1; fi
    if [ "$(wc -l <"$WORK/.err")" -ne 1 ]; then echo "stderr is not one line:"; cat "$WORK/.err"; return 1; fi
    grep -q -- "$pattern" "$WORK/.err" || { echo "stderr lacks '$pattern': $(cat "$WORK/.err")"; return 1; }
}
