#!/usr/bin/env python3
"""Reads a tet mesh with its integer-grid map, extracts the hex mesh with the hexex Python
package, prints the report, writes the hex mesh as .vtu and renders its boundary quads
off-screen (matplotlib, Agg backend) to a PNG.

usage: python3 Examples/python/extract_and_render.py [IN.hexex|IN.ovm] [--out-dir DIR] [--threads N]

Defaults: Examples/data/sphere.hexex, output in /tmp/hexex-python-example
(<name>.vtu, <name>-report.json, <name>.png). Needs the hexex package
(python3 -m pip install ./python) and matplotlib. Exit status: 0 all-hex mesh written,
3 written but not all-hex, 2 bad input.
"""

import argparse
import json
import pathlib
import sys

import numpy as np

import hexex

# The six faces of a VTK hexahedron, outward (counter-clockwise seen from outside).
HEX_FACES = np.array([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])


def boundary_quads(hexes):
    """The quads of ``hexes`` (h, 8) that belong to exactly one hex, as (q, 4) loops."""
    quads = hexes[:, HEX_FACES].reshape(-1, 4)
    _, first, counts = np.unique(np.sort(quads, axis=1), axis=0, return_index=True, return_counts=True)
    return quads[first[counts == 1]]


def render(points, quads, png, title):
    """Draws the quads shaded by a fixed light and saves ``png``."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    corners = points[quads]  # (q, 4, 3)
    normals = np.cross(corners[:, 2] - corners[:, 0], corners[:, 3] - corners[:, 1])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    light = np.array([0.4, -0.5, 0.77]) / np.linalg.norm([0.4, -0.5, 0.77])
    shade = 0.35 + 0.65 * np.clip(normals @ light, 0, 1)
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="3d")
    ax.add_collection3d(Poly3DCollection(corners, facecolors=plt.cm.Blues(1.0 - 0.6 * shade),
                                         edgecolors="k", linewidths=0.3))
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        set_lim(c - half, c + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=25, azim=-60)
    ax.set_axis_off()
    ax.set_title(title)
    fig.savefig(png, dpi=100, bbox_inches="tight")
    plt.close(fig)


def main(argv=None):
    here = pathlib.Path(__file__).resolve().parent
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("input", nargs="?", default=str(here.parent / "data" / "sphere.hexex"))
    ap.add_argument("--out-dir", default="/tmp/hexex-python-example")
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args(argv)

    try:
        tet_map = hexex.read_map(args.input)
    except ValueError as e:
        print(f"extract_and_render.py: error: {e}", file=sys.stderr)
        return 2
    result = hexex.extract(*tet_map, threads=args.threads)
    print(json.dumps(result.report, indent=2))

    out = pathlib.Path(args.out_dir)
    out.mkdir(parents=True, exist_ok=True)
    name = pathlib.Path(args.input).name.split(".")[0]
    vtu, png = out / f"{name}.vtu", out / f"{name}.png"
    hexex.write_hex_mesh(vtu, result)
    (out / f"{name}-report.json").write_text(json.dumps(result.report, indent=2) + "\n")
    quads = boundary_quads(result.hexes)
    render(result.points, quads, png, f"{name}: {len(result.hexes)} hexes, {len(quads)} boundary quads")
    print(f"wrote {vtu} ({len(result.hexes)} hexes, {len(result.points)} vertices, "
          f"{'valid all-hex' if result.valid_all_hex else 'NOT all-hex'}) and {png}")
    return 0 if result.valid_all_hex else 3


if __name__ == "__main__":
    sys.exit(main())
