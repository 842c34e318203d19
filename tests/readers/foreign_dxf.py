"""A DXF drawn by ezdxf (an independent writer) reads in quiltc as ezdxf
draws it: quiltc converts it to G-code (mm), and every point of either
outline lies within 0.1 mm of the other (a symmetric Hausdorff distance
between ezdxf's own flattening and quiltc's). Usage: foreign_dxf.py QUILTC DIR
"""
import math
import subprocess
import sys

import ezdxf
from ezdxf import units


def seg_dist(p, a, b):
    ax, ay = a
    bx, by = b
    dx, dy = bx - ax, by - ay
    L = dx * dx + dy * dy
    t = 0.0 if L == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L))
    return math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy)


def dist_to_polylines(p, lines):
    return min(seg_dist(p, l[i], l[i + 1]) for l in lines for i in range(len(l) - 1))


def main():
    quiltc, d = sys.argv[1], sys.argv[2]
    doc = ezdxf.new("R2010")
    doc.units = units.IN
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0, 0, 0, 0.5), (2, 0, 0, 0, 0), (2, 1)], format="xyseb")
    msp.add_arc((4, 1), 0.8, 30, 250)
    msp.add_circle((1, 4), 0.6)
    msp.add_ellipse((4, 4), major_axis=(1, 0.3), ratio=0.5)
    msp.add_open_spline([(0, 6), (1, 7), (2, 5.5), (3, 7), (4, 6)], degree=3)
    msp.add_rational_spline([(5, 6), (6, 7), (7, 5.5), (8, 7)], [1, 3, 0.5, 1], degree=2)
    # fit points only, as CAD programs store a curve drawn through points:
    # without end tangents, and with them
    msp.add_spline([(0, 9), (1, 10), (2.5, 8.5), (3, 10), (4.5, 9)])
    tangent = msp.add_spline([(5, 9), (6, 10.5), (7.5, 8.5), (9, 9.5)])
    tangent.dxf.start_tangent = (0, 1, 0)
    tangent.dxf.end_tangent = (1, -1, 0)
    src = f"{d}/foreign.dxf"
    doc.saveas(src)
    fit_only = sum(1 for e in msp.query("SPLINE") if e.fit_point_count() and not e.control_point_count())
    if fit_only != 2:
        sys.exit(f"ezdxf wrote {fit_only} fit-point-only splines, not 2")
    mm = 25.4
    ref = []
    for e in msp:
        pts = [(v.x * mm, v.y * mm) for v in ezdxf.path.make_path(e).flattening(0.0005)]
        ref.append(pts)
    out = f"{d}/foreign.gcode"
    subprocess.run([quiltc, "convert", src, out], check=True)
    pieces, cur = [], None
    for line in open(out):
        w = line.split()
        if not w or w[0] not in ("G0", "G1") or not w[1].startswith("X"):
            continue  # the pen lines (G0 Z5, G1 Z0)
        p = (float(w[1][1:]), float(w[2][1:]))
        if w[0] == "G0":
            cur = [p]
            pieces.append(cur)
        else:
            cur.append(p)
    worst_q = max(dist_to_polylines(p, ref) for pc in pieces for p in pc)
    worst_r = max(dist_to_polylines(p, pieces) for l in ref for p in l)
    print(f"pieces {len(pieces)} (ezdxf {len(ref)}), quiltc->ezdxf {worst_q:.4f} mm, "
          f"ezdxf->quiltc {worst_r:.4f} mm")
    ok = len(pieces) == len(ref) and worst_q <= 0.1 and worst_r <= 0.1
    sys.exit(0 if ok else 1)


main()
