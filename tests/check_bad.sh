#!/bin/sh
# The bad-input catalogue (tests/bad/cases.txt): each case runs quiltc in a
# fresh empty directory and must exit with its status, print exactly one
# stderr line containing its expected text, and leave no file behind.
# Lines starting with ! are open CLI bugs: run, reported as Ignored.
ROOT=$(pwd)
QC=${QC:-$ROOT/${BUILD:-build}/quiltc}
run=0 fail=0 ign=0
TMP=$(mktemp -d) || exit 1
trap 'rm -rf "$TMP"' EXIT

# one_case STATUS EXPECTED ARGS: 0 when the case holds, else 1 with $why set
one_case() {
    want=$1 expect=$2 args=$3
    dir=$(mktemp -d "$TMP/case.XXXXXX") || return 1
    out=/dev/null
    set --
    for a in $args; do
        case $a in
            '>'*) out=${a#>} ;;
            tests/*) set -- "$@" "$ROOT/$a" ;;
            *) set -- "$@" "$a" ;;
        esac
    done
    (cd "$dir" && exec "$QC" "$@" >"$out" 2>"$TMP/err")
    got=$?
    left=$(ls -A "$dir")
    rm -rf "$dir"
    if [ "$got" -ne "$want" ]; then
        why="exit $got, wanted $want: $(head -n 2 "$TMP/err" | tr '\n' ' ')"
        return 1
    fi
    if [ "$(wc -l <"$TMP/err")" -ne 1 ]; then
        why="$(wc -l <"$TMP/err") stderr lines: $(head -n 3 "$TMP/err" | tr '\n' '|')"
        return 1
    fi
    if ! grep -q -F -- "$expect" "$TMP/err"; then
        why="stderr lacks '$expect': $(cat "$TMP/err")"
        return 1
    fi
    if [ -n "$left" ]; then
        why="left behind: $(echo $left)"
        return 1
    fi
    return 0
}

if [ ! -x "$QC" ]; then
    echo "$0:1:quiltc_built:FAIL: $QC not built"
    printf '\n-----------------------\n1 Tests 1 Failures 0 Ignored\nFAIL\n'
    exit 1
fi
while IFS= read -r line; do
    case $line in '' | '#'*) continue ;; esac
    known=0
    case $line in '!'*) known=1 line=${line#!} ;; esac
    status=${line%%|*}
    rest=${line#*|}
    expect=${rest%%|*}
    args=${rest#*|}
    run=$((run + 1))
    name=$(echo "$args" | tr -c 'A-Za-z0-9\n' '_' | cut -c1-60)
    if one_case "$status" "$expect" "$args"; then
        if [ $known -eq 1 ]; then
            ign=$((ign + 1))
            echo "$0:$run:$name:IGNORE: open bug now passes: remove its '!' in tests/bad/cases.txt"
        else
            echo "$0:$run:$name:PASS"
        fi
    elif [ $known -eq 1 ]; then
        ign=$((ign + 1))
        echo "$0:$run:$name:IGNORE: open CLI bug: $why"
    else
        fail=$((fail + 1))
        echo "$0:$run:$name:FAIL: quiltc $args: $why"
    fi
done <tests/bad/cases.txt
printf '\n-----------------------\n%d Tests %d Failures %d Ignored\n' "$run" "$fail" "$ign"
[ "$fail" -eq 0 ] && echo OK || echo FAIL
[ "$fail" -eq 0 ]
