#!/usr/bin/env python3
"""Convert a wavyShearFoam packing to an LF_DEM text configuration file.

    foam2lfdem.py CASE_DIR OUTPUT_FILE [--time T]

Reads, from CASE_DIR/T (default T = 0, the packing written by makeSuspension):
    T/lagrangian/suspension/x      particle centres, inside the box [0, L)
    T/lagrangian/suspension/d      particle diameters
    T/uniform/suspensionState      box (Lx Ly Lz) and Lees-Edwards offset
and writes LF_DEM's text configuration ("base" format, as LF_DEM -g writes it):

    # np1 np2 vf lx ly lz vf1 vf2 dispx dispy
    # <values>
    x y z a
    ...

Axes. wavyShearFoam: flow x, gradient y, vorticity z (U = gammaDot y e_x).
LF_DEM: flow x, gradient z, vorticity y (U = gammaDot z e_x). So
LF_DEM (x, y, z) = ours (x, z, y), and (lx, ly, lz) = (Lx, Lz, Ly); the
offset of the image above (along x) is LF_DEM's dispx. Lengths are in
units of our a0 (the radius of the smaller spheres, 1 in our cases),
which is also LF_DEM's length unit when the small radius is 1.
Particles keep their order (line k = particle k of our files).
Python 3 standard library only.
"""
import argparse
import math
import os
import re
import sys


def strip_foam(text):
    """Remove C/C++ comments and the FoamFile header dictionary."""
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    text = re.sub(r"FoamFile\s*\{[^}]*\}", " ", text, flags=re.S)
    return text


def read_list(path, ncomp):
    """Read an OpenFOAM ascii List/Field of scalars (ncomp 1) or vectors (3).

    Handles 'N ( ... )' and the uniform form 'N { value }'."""
    with open(path) as f:
        body = strip_foam(f.read())
    m = re.search(r"(\d+)\s*([({])", body)
    if not m:
        raise ValueError(path + ": no list found")
    n = int(m.group(1))
    rest = body[m.end():]
    num = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
    if m.group(2) == "{":
        vals = [float(v) for v in re.findall(num, rest.split("}", 1)[0])]
        if len(vals) != ncomp:
            raise ValueError(path + ": bad uniform list")
        return [vals if ncomp > 1 else vals[0]] * n
    # list body up to the matching closing parenthesis
    depth, end = 1, None
    for i, c in enumerate(rest):
        if c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
            if depth == 0:
                end = i
                break
    if end is None:
        raise ValueError(path + ": unterminated list")
    vals = [float(v) for v in re.findall(num, rest[:end])]
    if len(vals) != n * ncomp:
        raise ValueError("%s: %d numbers for %d entries" % (path, len(vals), n))
    if ncomp == 1:
        return vals
    return [vals[3 * i:3 * i + 3] for i in range(n)]


def read_state(path):
    """Box and Lees-Edwards offset from uniform/suspensionState."""
    with open(path) as f:
        body = strip_foam(f.read())
    num = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
    m = re.search(r"\bbox\s*\(\s*(%s)\s+(%s)\s+(%s)\s*\)" % (num, num, num), body)
    if not m:
        raise ValueError(path + ": no box entry")
    box = [float(m.group(i)) for i in (1, 2, 3)]
    m = re.search(r"\boffset\s+(%s)\s*;" % num, body)
    offset = float(m.group(1)) if m else 0.0
    return box, offset


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("output")
    ap.add_argument("--time", default="0", help="time directory (default 0)")
    args = ap.parse_args()

    tdir = os.path.join(args.case, args.time)
    cloud = os.path.join(tdir, "lagrangian", "suspension")
    x = read_list(os.path.join(cloud, "x"), 3)
    d = read_list(os.path.join(cloud, "d"), 1)
    if len(x) != len(d):
        sys.exit("x and d differ in length")
    (Lx, Ly, Lz), offset = read_state(os.path.join(tdir, "uniform", "suspensionState"))

    radii = [0.5 * di for di in d]
    sizes = sorted(set(round(a, 12) for a in radii))
    if len(sizes) > 2:
        print("warning: %d distinct radii; np1/np2 count the smallest and the rest"
              % len(sizes), file=sys.stderr)
    a_small = sizes[0]
    small = [a for a in radii if round(a, 12) == a_small]
    large = [a for a in radii if round(a, 12) != a_small]
    V = Lx * Ly * Lz
    vol = lambda rs: sum(4.0 / 3.0 * math.pi * a ** 3 for a in rs)
    vf1, vf2 = vol(small) / V, vol(large) / V

    # LF_DEM axes: (x, y, z) = ours (x, z, y)
    lx, ly, lz = Lx, Lz, Ly
    with open(args.output, "w") as f:
        f.write("# np1 np2 vf lx ly lz vf1 vf2 dispx dispy\n")
        f.write("# %d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g 0\n"
                % (len(small), len(large), vf1 + vf2, lx, ly, lz, vf1, vf2, offset))
        for (px, py, pz), a in zip(x, radii):
            for c, L in ((px, Lx), (py, Ly), (pz, Lz)):
                if not (0 <= c < L):
                    sys.exit("particle outside the box [0, L): %r" % ((px, py, pz),))
            f.write("%.17g %.17g %.17g %.17g\n" % (px, pz, py, a))
    print("%s: N = %d (%d of radius %g, %d larger), phi = %.6f, box %g x %g x %g,"
          " LF_DEM axes (x, y, z) = ours (x, z, y)"
          % (args.output, len(radii), len(small), a_small, len(large), vf1 + vf2, lx, ly, lz))


if __name__ == "__main__":
    main()
