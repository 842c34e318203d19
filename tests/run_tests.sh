#!/bin/sh
# Runs every test binary given and every tests/check_*.sh, reads each one's
# Unity summary ("N Tests M Failures K Ignored") and prints the plain total
# line last. A runner that dies without its summary counts as one failure.
passed=0 failed=0 skipped=0
out=$(mktemp) || exit 1
trap 'rm -f "$out"' EXIT
for t in "$@" tests/check_*.sh; do
    [ -e "$t" ] || continue
    case "$t" in *.sh) cmd="sh $t" ;; *) cmd="$t" ;; esac
    echo "== $t"
    $cmd >"$out" 2>&1
    rc=$?
    grep -v ':PASS$' "$out" | grep -v '^$' | grep -v -- '^-----' | grep -v '^OK$'
    summary=$(grep -E '^[0-9]+ Tests [0-9]+ Failures [0-9]+ Ignored' "$out" | tail -n 1)
    if [ -z "$summary" ]; then
        echo "$t: exited $rc without a summary"
        failed=$((failed + 1))
        continue
    fi
    n=$(echo "$summary" | cut -d' ' -f1)
    f=$(echo "$summary" | cut -d' ' -f3)
    i=$(echo "$summary" | cut -d' ' -f5)
    passed=$((passed + n - f - i))
    failed=$((failed + f))
    skipped=$((skipped + i))
    if [ "$f" -eq 0 ] && [ "$rc" -ne 0 ]; then
        echo "$t: exited $rc"
        failed=$((failed + 1))
    fi
done
[ "$skipped" -gt 0 ] && echo "($skipped ignored: see the IGNORE lines above)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
