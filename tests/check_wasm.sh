#!/bin/sh
# The WebAssembly build and the preview page: `make wasm`, the bindings built
# natively, tests/wasm/identity.mjs (the module's bytes against the CLI's and
# the native bindings' for a corpus over every family) and
# tests/wasm/page.test.mjs (the page in headless chromium via playwright-core).
# Without emcc, node, chromium or node_modules (npm ci) the affected cases
# are reported as ignored. Prints Unity's summary line last.
BUILD=${BUILD:-build}
export BUILD
log=$BUILD/check_wasm
mkdir -p "$log"
tests=0 failures=0 ignored=0

case_fail() { tests=$((tests + 1)); failures=$((failures + 1)); echo "tests/check_wasm.sh:$tests:$1:FAIL: $2"; }
case_ignore() { tests=$((tests + 1)); ignored=$((ignored + 1)); echo "tests/check_wasm.sh:$tests:$1:IGNORE: $2"; }
case_pass() { tests=$((tests + 1)); echo "tests/check_wasm.sh:$tests:$1:PASS"; }
finish() {
    printf '\n-----------------------\n%d Tests %d Failures %d Ignored\n' "$tests" "$failures" "$ignored"
    [ "$failures" -eq 0 ] && echo OK || echo FAIL
    exit 0
}
# Adds a node script's summary to ours (its case lines are already printed).
run_node() {
    name=$1
    shift
    node "$@" >"$log/$name.log" 2>&1
    rc=$?
    grep -v ':PASS$' "$log/$name.log" | grep -E ':(FAIL|IGNORE)|^# '
    summary=$(grep -E '^[0-9]+ Tests [0-9]+ Failures [0-9]+ Ignored' "$log/$name.log" | tail -n 1)
    if [ -z "$summary" ]; then
        case_fail "$name" "exited $rc without a summary: $(tail -n 3 "$log/$name.log" | tr '\n' ' ')"
        return
    fi
    set -- $summary
    tests=$((tests + $1)) failures=$((failures + $3)) ignored=$((ignored + $5))
    [ "$3" -eq 0 ] && [ "$rc" -ne 0 ] && case_fail "$name" "exited $rc"
}

emcc=${EMCC:-emcc}
if ! command -v "$emcc" >/dev/null 2>&1; then
    case_ignore wasm_build "$emcc not installed (apt-get install emscripten)"
    finish
fi
if ! command -v node >/dev/null 2>&1; then
    case_ignore wasm_node "node not installed"
    finish
fi
# in parallel unless a parent make already shares its job slots
case " $MAKEFLAGS " in *jobserver*|*" -j"*) jobs= ;; *) jobs=-j$(nproc 2>/dev/null || echo 2) ;; esac
if ${MAKE:-make} --no-print-directory $jobs BUILD="$BUILD" wasm "$BUILD/tests/qcw_native" >"$log/make.log" 2>&1; then
    case_pass make_wasm
else
    case_fail make_wasm "$(grep -E 'error' "$log/make.log" | head -n 2 | tr '\n' ' ')"
    finish
fi
run_node identity tests/wasm/identity.mjs

if [ ! -d node_modules/playwright-core ]; then
    case_ignore browser_tests "node_modules/playwright-core missing (npm ci)"
elif [ ! -x "${CHROMIUM:-/usr/bin/chromium}" ]; then
    case_ignore browser_tests "${CHROMIUM:-/usr/bin/chromium} missing (apt-get install chromium)"
else
    run_node page tests/wasm/page.test.mjs
fi
finish
