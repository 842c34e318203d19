#!/bin/sh
# The man page renders without a troff warning (a line starting with '.'
# is a macro, and its text would be lost) and names every command that
# `quiltc --help` lists. Prints Unity's summary line last.
BUILD=${BUILD:-build}
tests=0 failures=0
tests=$((tests + 1))
if command -v man >/dev/null 2>&1; then
    warn=$(man --warnings -l docs/quiltc.1 2>&1 >/dev/null)
    if [ -n "$warn" ]; then
        echo "tests/check_man.sh:warnings:FAIL: $warn"
        failures=$((failures + 1))
    else
        echo "tests/check_man.sh:warnings:PASS"
    fi
else
    echo "tests/check_man.sh:warnings:FAIL: man is not installed"
    failures=$((failures + 1))
fi
for cmd in $("$BUILD/quiltc" --help 2>&1 | sed -n 's/^  \([a-z][a-z-]*\)  .*/\1/p'); do
    tests=$((tests + 1))
    if grep -q "^\.B quiltc $cmd" docs/quiltc.1; then
        echo "tests/check_man.sh:command_$cmd:PASS"
    else
        echo "tests/check_man.sh:command_$cmd:FAIL: docs/quiltc.1 has no '.B quiltc $cmd'"
        failures=$((failures + 1))
    fi
done
echo "$tests Tests $failures Failures 0 Ignored"
[ "$failures" -eq 0 ]
