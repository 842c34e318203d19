# Fuzz smoke: each libFuzzer target (tests/fuzz/) for FUZZ_RUNS inputs (30,000)
# with a fixed seed, on its seed corpus and regression inputs (6 targets,
# about 4 minutes with the build); open findings of tests/fuzz/known.txt are
# stepped around. Skipped without clang's libFuzzer.
set -euo pipefail
rt=$(clang -print-file-name=libclang_rt.fuzzer-x86_64.a 2>/dev/null || true)
if ! command -v clang >/dev/null || [ ! -f "$rt" ]; then
    echo "fuzz smoke skipped: clang with libFuzzer (libclang-rt-14-dev) is not installed"
    exit 0
fi
make -j2 fuzz-build >/dev/null
# A fixed seed and a fixed number of runs (well inside the time cap even on a
# loaded machine), so the smoke explores the same inputs on every CI run:
# new findings come from the long runs (make fuzz), not at random here.
FUZZ_FLAGS="-seed=1 -runs=${FUZZ_RUNS:-30000}" make fuzz FUZZ_SECONDS="${FUZZ_SECONDS:-120}"
