#!/usr/bin/env python3
"""Writes the pieced tops tests/test_quilt.c and tests/check_quilt.sh sew:
real blocks as a quilter draws them in Inkscape (one shape per patch, in
inches, y down). Run from the repository root; the outputs are committed."""
import math

HEAD = ('<svg xmlns="http://www.w3.org/2000/svg" '
        'xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" '
        'width="{w}in" height="{h}in" viewBox="0 0 {w} {h}">\n')


def fmt(v):
    s = '%.6f' % v
    return s.rstrip('0').rstrip('.') if '.' in s else s


def poly(pid, pts, fill, cls=None, label=None):
    a = ' class="%s"' % cls if cls else ''
    b = ' inkscape:label="%s"' % label if label else ''
    p = ' '.join('%s,%s' % (fmt(x), fmt(y)) for x, y in pts)
    return '<polygon id="%s"%s%s fill="%s" points="%s"/>\n' % (pid, a, b, fill, p)


def rect(pid, x, y, w, h, fill, cls=None):
    a = ' class="%s"' % cls if cls else ''
    return '<rect id="%s"%s x="%s" y="%s" width="%s" height="%s" fill="%s"/>\n' % (
        pid, a, fmt(x), fmt(y), fmt(w), fmt(h), fill)


def write(name, w, h, body):
    with open(name, 'w') as f:
        f.write(HEAD.format(w=fmt(w), h=fmt(h)) + body + '</svg>\n')


def nine_patch(x0=0, y0=0, s=4, prefix='p', dark='#1f3a93', light='#f5f0e1'):
    out = ''
    for r in range(3):
        for c in range(3):
            dk = (r + c) % 2 == 0
            out += rect('%s%d%d' % (prefix, r, c), x0 + c * s, y0 + r * s, s, s,
                        dark if dk else light, 'dark' if dk else 'light')
    return out


def rot(p, k, c=6.0):
    x, y = p[0] - c, p[1] - c
    for _ in range(k):
        x, y = -y, x
    return (x + c, y + c)


def sawtooth_star():
    """A 12 in sawtooth star: centre square, 4 corner squares and 4 flying
    geese (a goose and two star points each): 17 pieces."""
    out = rect('centre', 3, 3, 6, 6, '#c0392b', 'centre')
    for k, name in enumerate(['sw', 'nw', 'ne', 'se']):
        x, y = rot((0, 9), k)
        x2, y2 = rot((3, 12), k)
        out += rect('corner-' + name, min(x, x2), min(y, y2), 3, 3, '#f5f0e1', 'background')
    for k, side in enumerate(['bottom', 'left', 'top', 'right']):
        goose = [rot(p, k) for p in [(3, 12), (9, 12), (6, 9)]]
        left = [rot(p, k) for p in [(3, 9), (6, 9), (3, 12)]]
        right = [rot(p, k) for p in [(6, 9), (9, 9), (9, 12)]]
        out += poly('goose-' + side, goose, '#f5f0e1', 'background', 'Sky ' + side)
        out += poly('point-%s-a' % side, left, '#e67e22', 'point', 'Star point')
        out += poly('point-%s-b' % side, right, '#e67e22', 'point', 'Star point')
    return out


def log_cabin():
    """A 12 in log cabin: a 2 in centre and 1 in logs around it, 21 pieces."""
    x0, y0, x1, y1 = 5.0, 5.0, 7.0, 7.0
    out = rect('hearth', x0, y0, 2, 2, '#c0392b', 'hearth')
    k = 0
    while k < 20:
        side = k % 4
        fill = '#f5f0e1' if side < 2 else '#2c3e50'
        if side == 0:
            out += rect('log%d' % k, x1, y0, 1, y1 - y0, fill, 'log'); x1 += 1
        elif side == 1:
            out += rect('log%d' % k, x0, y1, x1 - x0, 1, fill, 'log'); y1 += 1
        elif side == 2:
            out += rect('log%d' % k, x0 - 1, y0, 1, y1 - y0, fill, 'log'); x0 -= 1
        else:
            out += rect('log%d' % k, x0, y0 - 1, x1 - x0, 1, fill, 'log'); y0 -= 1
        k += 1
    return out


def drunkards_path():
    """Four 4 in drunkard's path units (a quarter circle of radius 2.5 in a
    corner and the rest of the square), curved seams as SVG arcs."""
    out = ''
    r = 2.5
    for u in range(4):
        ox, oy = (u % 2) * 4, (u // 2) * 4
        k = u  # each unit turned a quarter more
        t = 'translate(%s %s) rotate(%d 2 2)' % (fmt(ox), fmt(oy), 90 * k)
        out += ('<path id="pie%d" class="pie" transform="%s" fill="#1f3a93" '
                'd="M0,0 L%s,0 A%s,%s 0 0 1 0,%s Z"/>\n') % (u, t, fmt(r), fmt(r), fmt(r), fmt(r))
        out += ('<path id="crust%d" class="crust" transform="%s" fill="#f5f0e1" '
                'd="M%s,0 L4,0 L4,4 L0,4 L0,%s A%s,%s 0 0 0 %s,0 Z"/>\n') % (
                    u, t, fmt(r), fmt(r), fmt(r), fmt(r), fmt(r))
    return out


def sashing_top():
    """Four 6 in nine-patches with 1 in sashing between them and a 2 in
    border: T-junctions where strips meet blocks."""
    out = ''
    b, s, blk = 2.0, 1.0, 6.0
    for i in range(2):
        for j in range(2):
            x = b + j * (blk + s)
            y = b + i * (blk + s)
            out += nine_patch(x, y, 2, 'b%d%d-' % (i, j))
    inner = 2 * blk + s
    out += rect('sash-v0', b + blk, b, s, blk, '#7f8c8d', 'sashing')
    out += rect('sash-v1', b + blk, b + blk + s, s, blk, '#7f8c8d', 'sashing')
    out += rect('sash-h', b, b + blk, inner, s, '#7f8c8d', 'sashing')
    w = inner + 2 * b
    out += rect('border-top', 0, 0, w, b, '#2c3e50', 'border')
    out += rect('border-bottom', 0, b + inner, w, b, '#2c3e50', 'border')
    out += rect('border-left', 0, b, b, inner, '#2c3e50', 'border')
    out += rect('border-right', b + inner, b, b, inner, '#2c3e50', 'border')
    return out, w


if __name__ == '__main__':
    write('tests/data/quilt/nine-patch.svg', 12, 12, nine_patch())
    write('examples/sawtooth-star.svg', 12, 12, sawtooth_star())
    write('tests/data/quilt/log-cabin.svg', 12, 12, log_cabin())
    write('tests/data/quilt/drunkards-path.svg', 8, 8, drunkards_path())
    body, w = sashing_top()
    write('tests/data/quilt/sashing.svg', w, w, body)
