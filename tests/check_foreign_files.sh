#!/bin/sh
# Files written by other programs read as they draw them: ezdxf writes a DXF
# of lightweight polylines with bulges, an arc, a circle, an ellipse and a
# spline in inches, and splines of fit points only (with and without end
# tangents); quiltc's reader must agree with ezdxf's own geometry
# within 0.1 mm (tests/readers/foreign_dxf.py). Prints Unity's summary line.
BUILD=${BUILD:-build}
dir=$BUILD/foreign
py=${PYTHON:-python3}
rm -rf "$dir" && mkdir -p "$dir"
if ! "$py" -c 'import ezdxf' 2>/dev/null; then
    echo "tests/check_foreign_files.sh:dxf_by_ezdxf:FAIL: ezdxf not installed (pip install ezdxf)"
    echo "1 Tests 1 Failures 0 Ignored"
    exit 1
fi
if out=$("$py" tests/readers/foreign_dxf.py "$BUILD/quiltc" "$dir" 2>&1); then
    echo "tests/check_foreign_files.sh:dxf_by_ezdxf:PASS ($out)"
    echo "1 Tests 0 Failures 0 Ignored"
else
    echo "tests/check_foreign_files.sh:dxf_by_ezdxf:FAIL: $out"
    echo "1 Tests 1 Failures 0 Ignored"
    exit 1
fi
