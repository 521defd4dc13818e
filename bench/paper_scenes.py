#!/usr/bin/env python3
"""The bench's synthetic scenes, as `.scene` text files (docs/input.md).

usage: python3 bench/paper_scenes.py OUTDIR

Writes star64.txt (the quality test: 64 alternating black and white wedges) and
paper_NAME_RULE.txt for the ten synthetic tests of Kallio 2007 (section 4 of the
paper: each test under even-odd and non-zero, 20 scenes).  The geometry follows
the test set of the paper's source release as described in bench/README.md
(logical canvas 320x240, every pattern built around (110, 110) and shifted by
(5, 5), opaque fills).  Deterministic: standard library only, coordinates
printed with 4 decimals, so every machine writes the same bytes.
"""
import math
import os
import sys

CANVAS = (320, 240)
CENTRE = 110.0
SHIFT = 5.0


def num(v):
    """Shortest decimal of v at 4 places ('-0' printed as '0')."""
    text = ("%.4f" % v).rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def scene_text(size, shapes, title):
    """shapes: list of (rule, (r, g, b, a), [contour, ...]); a contour is [(x, y), ...]."""
    lines = ["# " + title, "# written by bench/paper_scenes.py", "scene %d %d" % size]
    for rule, rgba, contours in shapes:
        lines.append("shape %s %d %d %d %d" % ((rule,) + tuple(rgba)))
        for c in contours:
            lines.append("contour " + " ".join("%s %s" % (num(x), num(y)) for x, y in c))
    return "\n".join(lines) + "\n"


def polar(r, a):
    # The original measures angles from +y towards +x.
    return (CENTRE + r * math.sin(a), CENTRE + r * math.cos(a))


# ---------------------------------------------------------------- the tests
# Each returns a list of (rgb, [contour, ...]): one shape per entry.

def star():
    """Pentagram {5/2} of radius 110: one self-intersecting 5-vertex contour."""
    turn = math.pi * 6 / 5
    return [((0, 0, 0), [[polar(110.0, math.pi + k * turn) for k in range(5)]])]


def siemens_star():
    """90 wedges of 2 degrees with 2-degree gaps, radius 110, in one contour."""
    step = math.pi / 90
    pts = []
    for n in range(90):
        pts += [polar(110.0, 2 * n * step), polar(110.0, (2 * n + 1) * step), (CENTRE, CENTRE)]
    return [((0, 0, 0), [pts])]


def circles():
    """36 rings 1 unit wide (outer radii 3..108), each two same-direction 100-gons."""
    contours = []
    for n in range(1, 37):
        outer = n * 3.0
        for r in (outer - 1.0, outer):
            contours.append([polar(r, 2 * math.pi * k / 100) for k in range(100)])
    return [((0, 0, 0), contours)]


def lcg_draws(seed):
    """The original's rand(): 32-bit LCG (1103515245, 12345) on a signed state, state >> 16 per draw."""
    state = seed & 0xFFFFFFFF
    while True:
        state = (1103515245 * state + 12345) & 0xFFFFFFFF
        yield (state - (1 << 32) if state & 0x80000000 else state) >> 16


def random_walk():
    """100 steps of length 100..101 (components uniform in [-101, 101]) inside radius 110, seed 75."""
    draw = lcg_draws(75)
    scale = 32767.0
    x = next(draw) * 110.0 / scale
    y = next(draw) * 110.0 / scale
    pts = []
    while len(pts) < 100:
        sx = next(draw) * 101.0 / scale
        sy = next(draw) * 101.0 / scale
        if not 100.0 ** 2 <= sx * sx + sy * sy <= 101.0 ** 2:
            continue
        if (x + sx) ** 2 + (y + sy) ** 2 > 110.0 ** 2:
            continue
        x, y = x + sx, y + sy
        pts.append((CENTRE + x, CENTRE + y))
    return [((0, 0, 0), [pts])]


def checkers():
    """A 220-unit square on a 101x101 grid: 50 columns and 50 rows on the odd lines, interleaved."""
    lo, hi = CENTRE - 110.0, CENTRE + 110.0
    cell = 220.0 / 101
    contours = []
    for n in range(50):
        a = lo + (2 * n + 1) * cell
        contours.append([(a, lo), (a + cell, lo), (a + cell, hi), (a, hi)])
        contours.append([(lo, a), (hi, a), (hi, a + cell), (lo, a + cell)])
    return [((0, 0, 0), contours)]


def squares(half, pitch, grid, nested, grow, segments, colour_step):
    """grid x grid objects, one shape each, row by row; each has `nested` square contours (the first
    2*half wide, each next `grow` wider), every side cut into `segments` edges, drawn from the top-left
    corner down, right, up, left; colours from black adding colour_step per object (mod 256)."""
    shapes = []
    first = CENTRE - pitch * grid / 2.0
    rgb = (0, 0, 0)
    for gy in range(grid):
        for gx in range(grid):
            cx, cy = first + gx * pitch, first + gy * pitch
            contours = []
            for i in range(nested):
                h = half + i * grow / 2
                corners = [(cx - h, cy - h), (cx - h, cy + h), (cx + h, cy + h), (cx + h, cy - h)]
                pts = []
                for k in range(4):
                    (x0, y0), (x1, y1) = corners[k], corners[(k + 1) % 4]
                    pts += [(x0 + (x1 - x0) * s / segments, y0 + (y1 - y0) * s / segments)
                            for s in range(segments)]
                contours.append(pts)
            shapes.append((rgb, contours))
            rgb = tuple((c + d) % 256 for c, d in zip(rgb, colour_step))
    return shapes


TESTS = [
    ("star", star, "pentagram, radius 110"),
    ("siemens_star", siemens_star, "Siemens star, 90 wedges of 2 degrees"),
    ("circles", circles, "36 concentric rings, 72 same-direction 100-gons"),
    ("random", random_walk, "random walk polygon, 100 vertices, seed 75"),
    ("checkers", checkers, "50 columns and 50 rows on a 101x101 grid"),
    ("square_basic", lambda: squares(109.875, 0.0, 1, 1, 0.0, 9, (15, 15, 15)),
     "one square, 9 edges per side"),
    ("square_many_edges", lambda: squares(109.875, 0.0, 1, 1, 0.0, 900, (15, 15, 15)),
     "one square, 900 edges per side"),
    ("square_long_edges", lambda: squares(109.875, 0.0, 1, 9, 0.0, 1, (15, 15, 15)),
     "one square as 9 coincident 4-edge contours"),
    ("squares_overdraw", lambda: squares(90.5, 39.5 / 8, 8, 1, 0.0, 1, (0xba, 0xdf, 0xab)),
     "8x8 overlapping squares, one shape each"),
    ("squares_small", lambda: squares(3.0, 106.0 / 16, 32, 2, -4.0, 9, (1, 1, 1)),
     "32x32 small objects with a nested square"),
]


def star64():
    """The quality test: 64 wedges of radius 0.47*256 about (128, 128), alternately black and white,
    each wedge's arc cut into 4 edges."""
    c, r = 128.0, 256 * 0.47
    wedges = ([], [])
    for i in range(64):
        a0, a1 = 2 * math.pi * i / 64, 2 * math.pi * (i + 1) / 64
        arc = [(c + r * math.cos(a0 + (a1 - a0) * k / 4), c + r * math.sin(a0 + (a1 - a0) * k / 4))
               for k in range(5)]
        wedges[i % 2].append([(c, c)] + arc)
    return [("nonzero", (0, 0, 0, 255), wedges[0]), ("nonzero", (255, 255, 255, 255), wedges[1])]


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: python3 bench/paper_scenes.py OUTDIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    files = {"star64.txt": scene_text((256, 256), star64(), "64 alternating black/white wedges (quality)")}
    for name, make, what in TESTS:
        shapes = [(rgb, [[(x + SHIFT, y + SHIFT) for x, y in c] for c in cs]) for rgb, cs in make()]
        for rule in ("evenodd", "nonzero"):
            files["paper_%s_%s.txt" % (name, rule)] = scene_text(
                CANVAS, [(rule, rgb + (255,), cs) for rgb, cs in shapes],
                "Kallio 2007 synthetic test '%s' (%s): %s; drawn 2x at 640x480 in the paper" % (name, rule, what))
    for name, text in files.items():
        tmp = os.path.join(out, name + ".tmp")
        with open(tmp, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
        os.replace(tmp, os.path.join(out, name))


if __name__ == "__main__":
    main()
