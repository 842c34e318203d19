# Fuzz smoke: each libFuzzer target (tests/fuzz/) for about 45 s of inputs
# at this machine's measured rates, with a fixed seed and a fixed count, on
# its seed corpus and regression inputs (6 targets, about 5 minutes with the
# build); open findings of tests/fuzz/known.txt are stepped around. Skipped
# without clang's libFuzzer.
set -euo pipefail
rt=$(clang -print-file-name=libclang_rt.fuzzer-x86_64.a 2>/dev/null || true)
if ! command -v clang >/dev/null || [ ! -f "$rt" ]; then
    echo "fuzz smoke skipped: clang with libFuzzer (libclang-rt-14-dev) is not installed"
    exit 0
fi
make -j2 fuzz-build >/dev/null
# A fixed seed and a fixed number of runs, so the smoke explores the same
# inputs on every CI run (new findings come from the long runs, make fuzz,
# not at random here); FUZZ_SECONDS caps each target on a slow machine,
# which then runs a prefix of the same inputs.
status=0
for spec in pat:1500000 job:500000 svg_region:300000 motif:200000 points:150000 generate:30000 read:250000; do
    t=${spec%%:*} n=${spec#*:}
    FUZZ_FLAGS="-seed=1 -runs=${FUZZ_RUNS:-$n}" make fuzz FUZZ_TARGETS="$t" \
        FUZZ_SECONDS="${FUZZ_SECONDS:-120}" || status=1
done
exit $status
