#!/bin/sh
# make lint's checker: passes the real core, catches a global and a printf.
. "$(dirname "$0")/cli_lib.sh"
ROOT=$(pwd)
LIB="$ROOT/${BUILD:-build}/libquiltc.a"

core_passes() { sh "$ROOT/tests/lint_core.sh" "$LIB"; }
rule_breaker_fails() {
    cc -c -fPIC "$ROOT/tests/fixtures/lint_bad.c" -o bad.o && ar rcs bad.a bad.o || return 1
    out=$(sh "$ROOT/tests/lint_core.sh" bad.a) && return 1
    echo "$out" | grep -q ' counter' && echo "$out" | grep -q 'printf'
}
check core_passes core_passes
check rule_breaker_fails rule_breaker_fails
finish
