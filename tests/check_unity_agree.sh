#!/bin/sh
# Our harness (tests/unity/) and a real Unity agree: tests/unity_agree/
# agree_cases.c, with known passing, failing and ignored cases, gives each
# case the outcome its name ends in under ours, and prints the very same
# lines under ThrowTheSwitch's Unity when one is found (UNITY_REAL, else
# ../shared/vendor/unity/src beside the repository; ignored without it).
ROOT=$(pwd)
REAL=${UNITY_REAL:-$ROOT/../shared/vendor/unity/src}
SRC=tests/unity_agree/agree_cases.c
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
CFLAGS="-std=c99 -Wall -Wextra -Werror -D_POSIX_C_SOURCE=200809L"
tests=0 failures=0 ignored=0
line() { tests=$((tests + 1)); echo "tests/check_unity_agree.sh:$tests:$1:$2"; }
pass() { line "$1" PASS; }
fail() { failures=$((failures + 1)); line "$1" "FAIL: $2"; }
ignore() { ignored=$((ignored + 1)); line "$1" "IGNORE: $2"; }

# outcomes FILE: "name outcome" per case line (PASS, FAIL or IGNORE).
outcomes() { sed -n 's/^[^:]*:[0-9]*:\([a-z0-9_]*\):\(PASS\|FAIL\|IGNORE\).*/\1 \2/p' "$1"; }

if ${CC:-cc} $CFLAGS -Itests/unity -o "$WORK/ours" "$SRC" tests/unity/unity.c -lm 2>"$WORK/err" &&
    "$WORK/ours" >"$WORK/ours.txt"; then
    wrong=$(outcomes "$WORK/ours.txt" | awk '
        { want = $1 ~ /_passes$/ ? "PASS" : $1 ~ /_fails$/ ? "FAIL" : $1 ~ /_ignored$/ ? "IGNORE" : "?" }
        want != $2 { printf "%s is %s ", $1, $2 }')
    n=$(grep -c 'RUN_TEST(' "$SRC")
    f=$(grep -c 'RUN_TEST([a-z0-9_]*_fails)' "$SRC")
    i=$(grep -c 'RUN_TEST([a-z0-9_]*_ignored)' "$SRC")
    if [ -n "$wrong" ]; then
        fail ours_gives_each_case_its_outcome "$wrong"
    elif ! grep -q "^$n Tests $f Failures $i Ignored" "$WORK/ours.txt"; then
        fail ours_gives_each_case_its_outcome "summary $(grep ' Tests ' "$WORK/ours.txt"), wanted $n $f $i"
    else
        pass ours_gives_each_case_its_outcome
    fi
else
    fail ours_gives_each_case_its_outcome "build or run failed: $(head -n 3 "$WORK/err" | tr '\n' ' ')"
fi

if [ ! -f "$REAL/unity.c" ] || [ ! -f "$REAL/unity_internals.h" ]; then
    ignore real_unity_prints_the_same_lines "no real Unity at $REAL (set UNITY_REAL)"
elif ! ${CC:-cc} $CFLAGS -I"$REAL" -DUNITY_INCLUDE_DOUBLE -DUNITY_SUPPORT_64 -o "$WORK/real" \
        "$SRC" "$REAL/unity.c" -lm 2>"$WORK/err"; then
    fail real_unity_prints_the_same_lines "build failed: $(head -n 3 "$WORK/err" | tr '\n' ' ')"
elif ! "$WORK/real" >"$WORK/real.txt"; then
    fail real_unity_prints_the_same_lines "the real-Unity build exited non-zero"
elif ! diff "$WORK/real.txt" "$WORK/ours.txt" >"$WORK/diff"; then
    fail real_unity_prints_the_same_lines "$(grep '^[<>]' "$WORK/diff" | head -n 4 | tr '\n' ' ')"
else
    pass real_unity_prints_the_same_lines
fi

printf '\n-----------------------\n%d Tests %d Failures %d Ignored\n' "$tests" "$failures" "$ignored"
[ "$failures" -eq 0 ] && echo OK || echo FAIL
