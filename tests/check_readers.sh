#!/bin/sh
# Independent readers of our machine files: test_io writes a sample plan in
# every format (QC_READERS_DIR), then ezdxf (DXF), qli (QLI), pystitch (PLT,
# QCC, IQP, G-code, BQM), hp2xx (PLT), svg.path (SVG) and pat-tools' line
# grammar (PAT) read them back and tests/readers/check_format.py compares the
# points with the plan within each format's resolution. A missing reader is a
# failure (CI installs them: .ci/apt-packages.txt, .ci/requirements.txt).
# Prints Unity's summary line last.
BUILD=${BUILD:-build}
dir=$BUILD/readers
bin=$BUILD/tests/test_io
py=${PYTHON:-python3}
tests=0 failures=0

fail() {
    echo "tests/check_readers.sh:$1:FAIL: $2"
    failures=$((failures + 1))
}

checks="pat-regex qli-qli_parser dxf-ezdxf plt-pystitch plt-hp2xx qcc-pystitch iqp-pystitch gcode-pystitch bqm-pystitch svg-svg.path"
rm -rf "$dir" && mkdir -p "$dir"
tests=$((tests + 1))
if [ ! -x "$bin" ]; then
    fail write_samples "$bin not built (make $bin)"
elif ! QC_READERS_DIR=$dir "$bin" >"$dir/test_io.log" 2>&1; then
    fail write_samples "$bin failed: $(grep FAIL "$dir/test_io.log" | head -n 1)"
else
    echo "tests/check_readers.sh:write_samples:PASS"
fi
for c in $checks; do
    tests=$((tests + 1))
    case $c in
    plt-hp2xx)
        if ! command -v hp2xx >/dev/null 2>&1; then
            fail "$c" "hp2xx not installed (apt-get install hp2xx)"
            continue
        fi ;;
    esac
    if ! command -v "$py" >/dev/null 2>&1; then
        fail "$c" "$py not installed"
        continue
    fi
    if msg=$("$py" tests/readers/check_format.py "$dir" "$c" 2>&1); then
        echo "tests/check_readers.sh:$c:PASS"
    else
        fail "$c" "$(echo "$msg" | tail -n 1)"
    fi
done
echo
echo "-----------------------"
echo "$tests Tests $failures Failures 0 Ignored"
if [ "$failures" -eq 0 ]; then echo OK; else echo FAIL; fi
[ "$failures" -eq 0 ]
