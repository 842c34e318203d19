#!/usr/bin/env python3
"""Reads one of quiltc's sample files with an independent reader and compares
the points it finds with sample.csv (the plan, in mm) within the format's
resolution. Usage: check_format.py DIR CHECK. Exit 0 and no output when the
file agrees; otherwise prints one line saying why and exits 1."""
import csv
import math
import os
import re
import subprocess
import sys

MM_PER_IN = 25.4


def load_plan(d):
    with open(os.path.join(d, "sample.csv")) as f:
        rows = list(csv.DictReader(f))
    return [(float(r["x_mm"]), float(r["y_mm"]), r["jump"] == "1") for r in rows]


def pieces(plan):
    out = []
    for x, y, j in plan:
        if j or not out:
            out.append([])
        out[-1].append((x, y))
    return out


class Mismatch(Exception):
    pass


def compare(name, got, want, tol, offset=(0.0, 0.0)):
    """got/want: lists of (x, y) in mm; tol in mm."""
    if len(got) != len(want):
        raise Mismatch("%s: read %d points, wrote %d" % (name, len(got), len(want)))
    for i, (g, w) in enumerate(zip(got, want)):
        dx = g[0] - offset[0] - w[0]
        dy = g[1] - offset[1] - w[1]
        if abs(dx) > tol or abs(dy) > tol:
            raise Mismatch("%s: point %d read (%.6f, %.6f), wrote (%.6f, %.6f) mm, tolerance %g mm"
                           % (name, i, g[0] - offset[0], g[1] - offset[1], w[0], w[1], tol))


def stitches_of(pattern):
    import pystitch
    return [(s[0], s[1]) for s in pattern.stitches if (s[2] & pystitch.COMMAND_MASK) == pystitch.STITCH]


def read_pystitch(reader, path):
    import pystitch
    return pystitch.EmbPattern.read_embroidery(reader, path)


def check_pat(d, plan):
    # the line grammar of pat2svg.py (textiles-lab/pat-tools)
    rx = re.compile(r"^N\d+G(\d+)X([\d.+-]+)Y([\d.+-]+)\r?$")
    got, jumps = [], []
    with open(os.path.join(d, "sample.pat"), newline="") as f:
        lines = f.read().split("\n")
    if lines[-1] != "" or not re.match(r"^N\d+M02\r$", lines[-2]):
        raise Mismatch("pat: the last line is not N<k>M02 CRLF")
    for n, line in enumerate(lines[:-2], 1):
        m = rx.match(line)
        if not m or not line.endswith("\r") or not line.startswith("N%dG" % n):
            raise Mismatch("pat: line %d %r does not match" % (n, line))
        got.append((float(m.group(2)) * MM_PER_IN, float(m.group(3)) * MM_PER_IN))
        jumps.append(int(m.group(1)) == 0)
    compare("pat", got, [(x, y) for x, y, _ in plan], 0.0005 * MM_PER_IN + 1e-9)
    if jumps != [j for _, _, j in plan]:
        raise Mismatch("pat: G00 lines are not the piece starts")


def check_qli(d, plan):
    from qli import qli_parser

    class Collect(qli_parser.QliExecutor):
        def __init__(self, program):
            qli_parser.QliExecutor.__init__(self, program)
            self.axes = (0, 1)
            self.relative = 0j
            self.cur = 0j
            self.needle = True
            self.points = []

        def doVectorMotion(self, index, command):
            self.axes = command.axes

        def doVectorPosition(self, index, command):
            a = (command.d1, command.d2)
            self.cur = a[self.axes[0]] + 1j * a[self.axes[1]] + self.relative
            self.points.append((self.cur, self.needle))

        def doVectorSequenceEnd(self, index, command):
            self.relative = self.cur

        def doClearSequence(self, index, command):
            self.cur = 0j

        def doNeedleOff(self, index, command):
            self.needle = False

        def doNeedleOn(self, index, command):
            self.needle = True

    path = os.path.join(d, "sample.qli")
    with open(path) as f:
        prog = qli_parser.QliProgram(path, qli_parser.Qli(f))
    c = Collect(prog)
    c.run()
    got = [(p.real * MM_PER_IN / 1000, p.imag * MM_PER_IN / 1000) for p, _ in c.points]
    compare("qli", got, [(x, y) for x, y, _ in plan], 0.0005 * MM_PER_IN + 1e-9)
    if [not on for _, on in c.points] != [j for _, _, j in plan]:
        raise Mismatch("qli: needle-off moves are not the piece starts")


def check_dxf(d, plan):
    import ezdxf
    doc = ezdxf.readfile(os.path.join(d, "sample.dxf"))
    if doc.header.get("$INSUNITS") != 4:
        raise Mismatch("dxf: $INSUNITS is %r, not 4 (mm)" % doc.header.get("$INSUNITS"))
    auditor = doc.audit()
    if auditor.has_errors:
        raise Mismatch("dxf: ezdxf audit found %d errors" % len(auditor.errors))
    polys = list(doc.modelspace().query("POLYLINE"))
    want = pieces(plan)
    if len(polys) != len(want):
        raise Mismatch("dxf: %d polylines for %d pieces" % (len(polys), len(want)))
    for k, (pl, w) in enumerate(zip(polys, want)):
        got = [(v.dxf.location[0], v.dxf.location[1]) for v in pl.vertices]
        compare("dxf polyline %d" % k, got, w, 0.00005 + 1e-9)


def check_plt_pystitch(d, plan):
    import pystitch
    pat = read_pystitch(pystitch.PltReader, os.path.join(d, "sample.plt"))
    got = [(x / 10, -y / 10) for x, y in stitches_of(pat)]
    compare("plt (pystitch)", got, [(x, y) for x, y, _ in plan], 0.0125 + 1e-9)


def check_plt_hp2xx(d, plan):
    import ezdxf
    out = os.path.join(d, "hp2xx-sample.dxf")
    r = subprocess.run(["hp2xx", "-t", "-m", "dxf", "-f", out,
                        os.path.join(d, "sample.plt")], capture_output=True, text=True,
                       stdin=subprocess.DEVNULL)
    if r.returncode != 0 or not os.path.exists(out):
        raise Mismatch("plt: hp2xx failed (%d): %s" % (r.returncode, r.stderr.strip()[:200]))
    log = r.stdout + r.stderr
    for what in (r"command\(s\) ignored:\s*(\d+)", r"Unexpected event\(s\):\s*(\d+)", r"(\S+): ignored"):
        m = re.search(what, log)
        if m and m.group(1) != "0":
            raise Mismatch("plt: hp2xx reports %r" % m.group(0))
    lines = list(ezdxf.readfile(out).modelspace().query("LINE"))
    segs = []
    for p in pieces(plan):
        segs += list(zip(p[:-1], p[1:]))
    if len(lines) != len(segs):
        raise Mismatch("plt: hp2xx drew %d pen-down lines, we sewed %d segments" % (len(lines), len(segs)))
    # hp2xx -t keeps true size (mm) but moves the picture: compare up to one translation
    s0 = lines[0].dxf.start
    off = (s0[0] - segs[0][0][0], s0[1] - segs[0][0][1])
    got = []
    want = []
    for ln, (a, b) in zip(lines, segs):
        got += [(ln.dxf.start[0], ln.dxf.start[1]), (ln.dxf.end[0], ln.dxf.end[1])]
        want += [a, b]
    compare("plt (hp2xx)", got, want, 0.0125 + 0.002, off)


def check_qcc(d, plan):
    import pystitch
    pat = read_pystitch(pystitch.QccReader, os.path.join(d, "sample.qcc"))
    got = [(x / 10, -y / 10) for x, y in stitches_of(pat)]
    compare("qcc", got, [(x, y) for x, y, _ in plan], 0.00005 * MM_PER_IN + 1e-9)


def check_iqp(d, plan):
    import pystitch
    pat = read_pystitch(pystitch.IqpReader, os.path.join(d, "sample.iqp"))
    got = [(x / 10, -y / 10) for x, y in stitches_of(pat)]
    # float32 inches: about 7 significant digits
    compare("iqp", got, [(x, y) for x, y, _ in plan], 1e-4)


def check_gcode(d, plan, name, ext, mm_per_unit, tol):
    import pystitch
    pat = read_pystitch(pystitch.GcodeReader, os.path.join(d, "sample" + ext))
    # pystitch assumes mm (1/10 mm per stitch unit) and flips both axes
    got = [(-x / 10 * mm_per_unit, -y / 10 * mm_per_unit) for x, y in stitches_of(pat)]
    compare(name, got, [(x, y) for x, y, _ in plan], tol)


def check_svg(d, plan):
    import xml.etree.ElementTree as ET
    from svg.path import parse_path, Move
    root = ET.parse(os.path.join(d, "sample.svg")).getroot()
    ns = "{http://www.w3.org/2000/svg}"
    w, h = root.get("width"), root.get("height")
    vb = [float(v) for v in root.get("viewBox").split()]
    if not (w.endswith("mm") and h.endswith("mm")) or float(w[:-2]) != vb[2] or float(h[:-2]) != vb[3]:
        raise Mismatch("svg: width/height %s %s do not match viewBox %s" % (w, h, vb))
    g = [e for e in root.iter(ns + "g") if e.get("id") == "path"]
    if len(g) != 1:
        raise Mismatch("svg: no single <g id=\"path\">")
    path = parse_path(g[0].find(ns + "path").get("d"))
    got, starts = [], []
    for seg in path:
        if isinstance(seg, Move):
            got.append((seg.end.real, -seg.end.imag))
            starts.append(True)
        else:
            got.append((seg.end.real, -seg.end.imag))
            starts.append(False)
    x0, y0, _ = plan[0]
    compare("svg", got, [(x, y) for x, y, _ in plan], 0.001 + 1e-9, (got[0][0] - x0, got[0][1] - y0))
    if starts != [j for _, _, j in plan]:
        raise Mismatch("svg: moveto commands are not the piece starts")


CHECKS = {
    "pat-regex": check_pat,
    "qli-qli_parser": check_qli,
    "dxf-ezdxf": check_dxf,
    "plt-pystitch": check_plt_pystitch,
    "plt-hp2xx": check_plt_hp2xx,
    "qcc-pystitch": check_qcc,
    "iqp-pystitch": check_iqp,
    "gcode-pystitch": lambda d, p: check_gcode(d, p, "gcode", ".gcode", 1.0, 0.0005 + 1e-9),
    "bqm-pystitch": lambda d, p: check_gcode(d, p, "bqm", ".bqm", MM_PER_IN, 0.00005 * MM_PER_IN + 1e-9),
    "svg-svg.path": check_svg,
}


def main():
    if len(sys.argv) == 2 and sys.argv[1] == "--list":
        print(" ".join(CHECKS))
        return 0
    d, name = sys.argv[1], sys.argv[2]
    try:
        CHECKS[name](d, load_plan(d))
    except Mismatch as e:
        print(e)
        return 1
    except ImportError as e:
        print("%s: reader missing: %s" % (name, e))
        return 1
    except Exception as e:  # a reader that chokes on our file fails the check
        print("%s: %s: %s" % (name, type(e).__name__, str(e).splitlines()[0] if str(e) else ""))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
