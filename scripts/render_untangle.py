#!/usr/bin/python3
"""Render a hex mesh before and after untangling side by side, inverted hexes highlighted.

usage: python3 scripts/render_untangle.py BEFORE.vtu AFTER.vtu OUT.png [--title T]
                                          [--view ELEV,AZIM] [--size INCHES] [--dpi N]

BEFORE and AFTER are VTK XML UnstructuredGrid files with ASCII data (`--encoding ascii`)
of the same mesh (same hexes, moved vertices), e.g. `hexex extract` and `hexex untangle`
outputs. Both panels draw the boundary quads translucent; the left panel draws every hex
with a corner Jacobian <= 0 (the 8 corner tets, as HexEx::computeQuality counts them) in
red, the right panel draws the same hexes after untangling in green (and any hex still
inverted in red). Reads the files with read_vtu() of scripts/render_boundary.py.
Exit status: 0 written, 1 matplotlib missing, 2 bad input or usage.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_boundary import VTK_HEXAHEDRON, boundary_faces, fail, read_vtu  # noqa: E402

# Corner frames of a VTK hex: (corner, a, b, c), Jacobian det(p[a]-p[corner], ...) > 0 when valid.
CORNERS = [(0, 1, 3, 4), (1, 2, 0, 5), (2, 3, 1, 6), (3, 0, 2, 7), (4, 7, 5, 0), (5, 4, 6, 1), (6, 5, 7, 2), (7, 6, 4, 3)]


def hex_vertices(faces):
    """The 8 VTK-ordered vertices of a hex cell given by read_vtu() (faces 0-3-2-1, 4-5-6-7, ...)."""
    b, t = faces[0], faces[1]
    return [b[0], b[3], b[2], b[1], t[0], t[1], t[2], t[3]]


def inverted(points, v):
    """True if a corner Jacobian of hex v (8 vertex indices) is <= 0."""
    for c, a, b, d in CORNERS:
        o = points[v[c]]
        e1 = [points[v[a]][i] - o[i] for i in range(3)]
        e2 = [points[v[b]][i] - o[i] for i in range(3)]
        e3 = [points[v[d]][i] - o[i] for i in range(3)]
        det = (e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
               e1[2] * (e2[0] * e3[1] - e2[1] * e3[0]))
        if not det > 0:
            return True
    return False


def main():
    ap = argparse.ArgumentParser(description="Render a hex mesh before/after untangling to PNG.")
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("output")
    ap.add_argument("--title", default=None)
    ap.add_argument("--view", default="25,-55", help="camera elevation,azimuth in degrees")
    ap.add_argument("--size", type=float, default=5.0, help="height of the figure in inches")
    ap.add_argument("--dpi", type=int, default=100)
    args = ap.parse_args()
    try:
        elev, azim = (float(s) for s in args.view.split(","))
    except ValueError:
        fail("--view expects ELEV,AZIM, e.g. 25,-55")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    except ImportError:
        print("render_untangle.py: matplotlib is not available to %s" % sys.executable, file=sys.stderr)
        sys.exit(1)

    meshes = [read_vtu(args.before), read_vtu(args.after)]
    hexes = [[hex_vertices(f) for t, f in cells if t == VTK_HEXAHEDRON] for _, cells in meshes]
    if len(hexes[0]) != len(hexes[1]) or any(a != b for a, b in zip(hexes[0], hexes[1])):
        fail("BEFORE and AFTER must have the same hexes")
    bad_before = [i for i, v in enumerate(hexes[0]) if inverted(meshes[0][0], v)]
    bad_after = set(i for i, v in enumerate(hexes[1]) if inverted(meshes[1][0], v))

    pts = meshes[0][0] + meshes[1][0]
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    mid = [(l + h) / 2 for l, h in zip(lo, hi)]
    half = [max(h - l, 0.05 * max(hh - ll for ll, hh in zip(lo, hi))) / 2 for l, h in zip(lo, hi)]

    fig = plt.figure(figsize=(2 * args.size, args.size * 1.05), dpi=args.dpi)
    for k, (points, cells) in enumerate(meshes):
        ax = fig.add_axes((0.5 * k, 0, 0.5, 0.9), projection="3d")
        shell = [[points[v] for v in f] for f, _ in boundary_faces(cells)]
        ax.add_collection3d(Poly3DCollection(shell, facecolors=(0.55, 0.7, 0.85, 0.10),
                                             edgecolors=(0.2, 0.25, 0.35, 0.35), linewidths=0.4))
        polys, colors = [], []
        for i in bad_before:
            v = hexes[k][i]
            red = k == 0 or i in bad_after
            for f, _ in [(face, 0) for face in ([v[0], v[3], v[2], v[1]], [v[4], v[5], v[6], v[7]], [v[0], v[1], v[5], v[4]],
                                                  [v[1], v[2], v[6], v[5]], [v[2], v[3], v[7], v[6]], [v[3], v[0], v[4], v[7]])]:
                polys.append([points[w] for w in f])
                colors.append((0.88, 0.25, 0.25, 0.85) if red else (0.25, 0.7, 0.35, 0.85))
        ax.add_collection3d(Poly3DCollection(polys, facecolors=colors, edgecolors=(0.1, 0.1, 0.1, 0.8), linewidths=0.5))
        ax.set_xlim(mid[0] - half[0], mid[0] + half[0])
        ax.set_ylim(mid[1] - half[1], mid[1] + half[1])
        ax.set_zlim(mid[2] - half[2], mid[2] + half[2])
        try:
            ax.set_box_aspect([2 * h for h in half], zoom=1.15)
        except (TypeError, AttributeError):
            pass
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        n_bad = len(bad_before) if k == 0 else len(bad_after)
        label = ("before: %d inverted hexes (red)" % n_bad) if k == 0 else \
            ("after untangling: %d inverted; the same %d hexes in green" % (n_bad, len(bad_before)))
        ax.set_title(label, fontsize=10, y=0.98)
    n = len(hexes[0])
    fig.suptitle((args.title + "\n" if args.title else "") + "%d hexes, boundary translucent" % n, fontsize=11, y=0.99)
    try:
        fig.savefig(args.output, dpi=args.dpi, bbox_inches="tight", pad_inches=0.1)
    except OSError as e:
        fail("%s: cannot write: %s" % (args.output, e))
    print("wrote %s: %d hexes, %d inverted before, %d after" % (args.output, n, len(bad_before), len(bad_after)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
