#!/usr/bin/python3
"""Render a hex mesh before and after `hexex optimize`: the worst hexes in 3D and the
histograms of the scaled Jacobian.

usage: python3 scripts/render_optimize.py BEFORE.vtu AFTER.vtu OUT.png [--title T]
                                          [--view ELEV,AZIM] [--worst K] [--size INCHES] [--dpi N]

BEFORE and AFTER are VTK XML UnstructuredGrid files with ASCII data (`--encoding ascii`)
of the same mesh (same hexes, moved vertices). The two 3D panels draw the boundary quads
translucent and the K hexes (default 12) with the smallest scaled Jacobian (SJ, minimum of
the 8 corner values, as HexEx::hexScaledJacobian) of BEFORE, coloured by their SJ in each
mesh; the third panel shows the SJ histograms of both meshes (bins of 0.1 over [-1, 1], the
bins of OptimizeReport). Reads the files with read_vtu() of scripts/render_boundary.py.
Exit status: 0 written, 1 matplotlib missing, 2 bad input or usage.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_boundary import VTK_HEXAHEDRON, boundary_faces, fail, read_vtu  # noqa: E402
from render_untangle import CORNERS, hex_vertices  # noqa: E402


def scaled_jacobian(points, v):
    """Minimum over the 8 corners of det(e1, e2, e3) / (|e1| |e2| |e3|) of hex v."""
    worst = 1.0
    for c, a, b, d in CORNERS:
        o = points[v[c]]
        e = [[points[v[w]][i] - o[i] for i in range(3)] for w in (a, b, d)]
        det = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
               e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]))
        length = math.prod(math.sqrt(sum(x * x for x in ei)) for ei in e)
        worst = min(worst, det / length if length > 0 else 0.0)
    return worst


def main():
    ap = argparse.ArgumentParser(description="Render a hex mesh before/after optimisation to PNG.")
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("output")
    ap.add_argument("--title", default=None)
    ap.add_argument("--view", default="25,-55", help="camera elevation,azimuth in degrees")
    ap.add_argument("--worst", type=int, default=12, help="hexes drawn (the worst of BEFORE)")
    ap.add_argument("--size", type=float, default=4.5, help="height of the figure in inches")
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
        from matplotlib import cm
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    except ImportError:
        print("render_optimize.py: matplotlib is not available to %s" % sys.executable, file=sys.stderr)
        sys.exit(1)

    meshes = [read_vtu(args.before), read_vtu(args.after)]
    hexes = [[hex_vertices(f) for t, f in cells if t == VTK_HEXAHEDRON] for _, cells in meshes]
    if not hexes[0] or len(hexes[0]) != len(hexes[1]) or any(a != b for a, b in zip(hexes[0], hexes[1])):
        fail("BEFORE and AFTER must have the same (non-empty) hexes")
    sj = [[scaled_jacobian(m[0], v) for v in hx] for m, hx in zip(meshes, hexes)]
    worst = sorted(range(len(sj[0])), key=lambda i: sj[0][i])[:max(args.worst, 0)]

    pts = meshes[0][0] + meshes[1][0]
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    mid = [(l + h) / 2 for l, h in zip(lo, hi)]
    half = [max(h - l, 0.05 * max(hh - ll for ll, hh in zip(lo, hi))) / 2 for l, h in zip(lo, hi)]
    cmap = cm.get_cmap("RdYlGn")

    fig = plt.figure(figsize=(3.2 * args.size, args.size * 1.05), dpi=args.dpi)
    for k, (points, cells) in enumerate(meshes):
        ax = fig.add_axes((0.33 * k, 0, 0.33, 0.88), projection="3d")
        shell = [[points[v] for v in f] for f, _ in boundary_faces(cells)]
        ax.add_collection3d(Poly3DCollection(shell, facecolors=(0.55, 0.7, 0.85, 0.08),
                                             edgecolors=(0.2, 0.25, 0.35, 0.3), linewidths=0.3))
        polys, colors = [], []
        for i in worst:
            v = hexes[k][i]
            for f in ([v[0], v[3], v[2], v[1]], [v[4], v[5], v[6], v[7]], [v[0], v[1], v[5], v[4]],
                      [v[1], v[2], v[6], v[5]], [v[2], v[3], v[7], v[6]], [v[3], v[0], v[4], v[7]]):
                polys.append([points[w] for w in f])
                colors.append(cmap(max(0.0, min(1.0, sj[k][i]))))
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
        ax.set_title("%s: worst SJ %.3f, mean %.3f" % ("before" if k == 0 else "after", min(sj[k]),
                                                       sum(sj[k]) / len(sj[k])), fontsize=10, y=0.98)
    ax = fig.add_axes((0.70, 0.12, 0.28, 0.7))
    bins = [-1 + 0.1 * i for i in range(21)]
    ax.hist([sj[0], sj[1]], bins=bins, label=["before", "after"], color=["#d9534f", "#5cb85c"])
    ax.set_yscale("log")
    ax.set_xlabel("scaled Jacobian")
    ax.set_ylabel("hexes")
    ax.legend(fontsize=9)
    ax.set_title("histogram (bins of 0.1)", fontsize=10)
    n = len(hexes[0])
    fig.suptitle((args.title + "\n" if args.title else "") +
                 "%d hexes; the %d worst of BEFORE drawn, coloured by SJ" % (n, len(worst)), fontsize=11, y=0.99)
    try:
        fig.savefig(args.output, dpi=args.dpi, bbox_inches="tight", pad_inches=0.1)
    except OSError as e:
        fail("%s: cannot write: %s" % (args.output, e))
    print("wrote %s: %d hexes, worst SJ %.4f -> %.4f" % (args.output, n, min(sj[0]), min(sj[1])))
    return 0


if __name__ == "__main__":
    sys.exit(main())
