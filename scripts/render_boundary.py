#!/usr/bin/python3
"""Render the boundary quads of a hex mesh written by `hexex extract -o OUT.vtu` to PNG.

usage: /usr/bin/python3 scripts/render_boundary.py IN.vtu OUT.png [--title T]
                                                   [--view ELEV,AZIM] [--size INCHES] [--dpi N]

The .vtu is the VTK XML UnstructuredGrid (ASCII) that src/HexEx/IO/HexMeshWriters.cc
writes; it is parsed with xml.etree only. Hexahedra (VTK type 12, vertex order 0-1-2-3
bottom, 4-5-6-7 top, 4 above 0) contribute their six faces; a face used by exactly one hex
is a boundary quad. Polyhedra (VTK type 42, from a map the extractor could not fully
resolve) contribute their faces from the `faces` array the same way and are drawn in red.
Faces are shaded by the angle of their normal to a fixed light and drawn with their edges.

Needs matplotlib: on Debian, `apt-get install python3-matplotlib` and run this script with
/usr/bin/python3 (a pyenv or virtualenv python may not see the Debian package).
Exit status: 0 written, 1 matplotlib missing, 2 bad input or usage.
"""

import argparse
import math
import sys
import xml.etree.ElementTree as ET

# Faces of a VTK hexahedron, each oriented outward (counter-clockwise seen from outside)
# for a positively oriented hex (bottom 0-1-2-3 counter-clockwise seen from the top).
HEX_FACES = [
    (0, 3, 2, 1),  # bottom
    (4, 5, 6, 7),  # top
    (0, 1, 5, 4),
    (1, 2, 6, 5),
    (2, 3, 7, 6),
    (3, 0, 4, 7),
]
VTK_HEXAHEDRON = 12
VTK_POLYHEDRON = 42


def fail(msg, code=2):
    print("render_boundary.py: " + msg, file=sys.stderr)
    sys.exit(code)


def read_vtu(path):
    """Returns (points, cells) with cells a list of (type, list of faces as vertex lists)."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        fail("%s: cannot read VTK XML: %s" % (path, e))
    if root.tag != "VTKFile" or root.get("type") != "UnstructuredGrid":
        fail("%s: not a VTK XML UnstructuredGrid file" % path)
    if root.find(".//AppendedData") is not None:
        fail("%s: appended (binary) data is not supported; expected ASCII DataArrays" % path)

    def array(parent, name, conv):
        for da in parent.iter("DataArray"):
            if da.get("Name") == name:
                if da.get("format", "ascii") != "ascii":
                    fail("%s: DataArray %s is not ASCII" % (path, name))
                try:
                    return [conv(t) for t in (da.text or "").split()]
                except ValueError as e:
                    fail("%s: DataArray %s: %s" % (path, name, e))
        return None

    piece = root.find("./UnstructuredGrid/Piece")
    if piece is None:
        fail("%s: no <Piece>" % path)
    pts_el = piece.find("Points")
    cells_el = piece.find("Cells")
    if pts_el is None or cells_el is None:
        fail("%s: <Points> or <Cells> missing" % path)
    flat = None
    for da in pts_el.iter("DataArray"):
        flat = [float(t) for t in (da.text or "").split()]
        break
    if flat is None or len(flat) % 3:
        fail("%s: bad Points array" % path)
    points = [tuple(flat[i:i + 3]) for i in range(0, len(flat), 3)]
    conn = array(cells_el, "connectivity", int)
    offsets = array(cells_el, "offsets", int)
    types = array(cells_el, "types", int)
    if conn is None or offsets is None or types is None or len(offsets) != len(types):
        fail("%s: connectivity/offsets/types missing or inconsistent" % path)
    faces = array(cells_el, "faces", int)
    faceoffsets = array(cells_el, "faceoffsets", int)

    cells = []
    start = 0
    for c, (end, t) in enumerate(zip(offsets, types)):
        verts = conn[start:end]
        start = end
        if any(v < 0 or v >= len(points) for v in verts):
            fail("%s: cell %d references a vertex out of range" % (path, c))
        if t == VTK_HEXAHEDRON:
            if len(verts) != 8:
                fail("%s: hexahedron %d has %d vertices" % (path, c, len(verts)))
            cells.append((t, [[verts[i] for i in f] for f in HEX_FACES]))
        elif t == VTK_POLYHEDRON and faces is not None and faceoffsets is not None:
            # faces stream of this cell ends at faceoffsets[c]; it starts with the face count.
            fend = faceoffsets[c]
            fstart = max([o for o in faceoffsets[:c] if o >= 0], default=0)
            stream = faces[fstart:fend]
            nf, k, fl = stream[0], 1, []
            for _ in range(nf):
                n = stream[k]
                fl.append(stream[k + 1:k + 1 + n])
                k += 1 + n
            cells.append((t, fl))
        else:
            print("render_boundary.py: warning: cell %d of VTK type %d skipped" % (c, t), file=sys.stderr)
    return points, cells


def boundary_faces(cells):
    """Faces used by exactly one cell, as (vertex list, is_polyhedron)."""
    count = {}
    first = {}
    for t, faces in cells:
        for f in faces:
            key = tuple(sorted(f))
            count[key] = count.get(key, 0) + 1
            first.setdefault(key, (f, t == VTK_POLYHEDRON))
    return [first[k] for k, n in count.items() if n == 1]


def main():
    ap = argparse.ArgumentParser(description="Render the boundary quads of a hexex .vtu output to PNG.")
    ap.add_argument("input", help="hex mesh, VTK XML UnstructuredGrid ASCII (.vtu)")
    ap.add_argument("output", help="PNG to write")
    ap.add_argument("--title", default=None, help="title drawn above the picture")
    ap.add_argument("--view", default="25,-55", help="camera elevation,azimuth in degrees (default 25,-55)")
    ap.add_argument("--size", type=float, default=6.0, help="figure size in inches (default 6)")
    ap.add_argument("--dpi", type=int, default=100, help="resolution (default 100)")
    ap.add_argument("--color", default="#8fb8de", help="face colour of hex boundary quads")
    args = ap.parse_args()
    try:
        elev, azim = (float(s) for s in args.view.split(","))
    except ValueError:
        fail("--view expects ELEV,AZIM, e.g. 25,-55")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.colors import to_rgb
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    except ImportError:
        print("render_boundary.py: matplotlib is not available to %s.\n"
              "Install it (Debian: apt-get install python3-matplotlib) and run this script with "
              "/usr/bin/python3." % sys.executable, file=sys.stderr)
        sys.exit(1)

    points, cells = read_vtu(args.input)
    bfaces = boundary_faces(cells)
    if not bfaces:
        fail("%s: no boundary faces (no cells?)" % args.input)

    # Light direction from the camera side: view direction from elev/azim, tilted up a bit.
    e, a = math.radians(elev + 20), math.radians(azim - 30)
    light = (math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e))

    polys, colors = [], []
    base = to_rgb(args.color)
    bad = to_rgb("#e05050")
    for f, is_poly in bfaces:
        P = [points[v] for v in f]
        # Newell normal: robust for non-planar quads.
        nx = ny = nz = 0.0
        for i in range(len(P)):
            x0, y0, z0 = P[i]
            x1, y1, z1 = P[(i + 1) % len(P)]
            nx += (y0 - y1) * (z0 + z1)
            ny += (z0 - z1) * (x0 + x1)
            nz += (x0 - x1) * (y0 + y1)
        ln = math.sqrt(nx * nx + ny * ny + nz * nz) or 1.0
        d = abs(nx * light[0] + ny * light[1] + nz * light[2]) / ln
        s = 0.35 + 0.65 * d
        c = bad if is_poly else base
        polys.append(P)
        colors.append(tuple(min(1.0, ch * s + 0.08) for ch in c))

    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    zs = [p[2] for p in points]
    lo = (min(xs), min(ys), min(zs))
    hi = (max(xs), max(ys), max(zs))
    mid = [(l + h) / 2 for l, h in zip(lo, hi)]
    big = max(h - l for l, h in zip(lo, hi)) or 1.0
    # Equal scale on all axes; the box follows the data's extents (at least 5% of the largest).
    half = [max(h - l, 0.05 * big) / 2 for l, h in zip(lo, hi)]

    fig = plt.figure(figsize=(args.size, args.size * 1.08), dpi=args.dpi)
    ax = fig.add_axes((0, 0, 1, 0.92), projection="3d")
    n = len(polys)
    lw = 0.6 if n < 2000 else (0.3 if n < 20000 else 0.12)
    edge = (0.1, 0.1, 0.15) if n < 2000 else (0.15, 0.17, 0.25)
    coll = Poly3DCollection(polys, facecolors=colors, edgecolors=edge, linewidths=lw)
    ax.add_collection3d(coll)
    ax.set_xlim(mid[0] - half[0], mid[0] + half[0])
    ax.set_ylim(mid[1] - half[1], mid[1] + half[1])
    ax.set_zlim(mid[2] - half[2], mid[2] + half[2])
    try:
        ax.set_box_aspect([2 * h for h in half], zoom=1.1)
    except TypeError:  # matplotlib < 3.3.x: no zoom
        ax.set_box_aspect([2 * h for h in half])
    except AttributeError:  # very old matplotlib: no box aspect
        pass
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()
    n_poly = sum(1 for t, _ in cells if t == VTK_POLYHEDRON)
    n_hex = len(cells) - n_poly
    sub = "%d hexes, %d boundary quads" % (n_hex, n)
    if n_poly:
        sub += ", %d non-hex cells (red)" % n_poly
    heading = (args.title + "\n" if args.title else "") + sub
    fig.suptitle(heading, fontsize=11, y=0.985)
    try:
        fig.savefig(args.output, dpi=args.dpi, bbox_inches="tight", pad_inches=0.15)
    except OSError as e:
        fail("%s: cannot write: %s" % (args.output, e))
    print("wrote %s: %d hexes, %d boundary faces" % (args.output, n_hex, n))
    return 0


if __name__ == "__main__":
    sys.exit(main())
