#!/usr/bin/python3
"""Draw the edge arcs of an extraction over its input tet mesh, to PNG.

usage: /usr/bin/python3 scripts/render_arcs.py IN.hexex ARCS.vtu OUT.png [--title T]
                                               [--view ELEV,AZIM] [--size INCHES] [--dpi N]

IN.hexex is the input (text .hexex: vertices, then tets with their parameters); ARCS.vtu
the file `hexex extract IN.hexex -o ... --edge-arcs ARCS.vtu` wrote (ASCII VTK XML, one
VTK_POLY_LINE per hex edge arc). The tet mesh is drawn as its boundary triangles (light,
translucent) and all its edges (thin grey lines); the arcs on top in colour, with their
end points (the hex vertices) as dots. Parsed with xml.etree only.

Needs matplotlib (Debian: apt-get install python3-matplotlib, run with /usr/bin/python3).
Exit status: 0 written, 1 matplotlib missing, 2 bad input or usage.
"""

import argparse
import sys
import xml.etree.ElementTree as ET


def fail(msg, code=2):
    print("render_arcs.py: " + msg, file=sys.stderr)
    sys.exit(code)


def read_hexex(path):
    try:
        tokens = open(path).read().split()
        nv = int(tokens[0])
        pts = [tuple(float(t) for t in tokens[1 + 3 * i:4 + 3 * i]) for i in range(nv)]
        k = 1 + 3 * nv
        nt = int(tokens[k])
        k += 1
        tets = []
        for _ in range(nt):
            tets.append(tuple(int(t) for t in tokens[k:k + 4]))
            k += 16
    except (OSError, ValueError, IndexError) as e:
        fail(f"{path}: cannot read the .hexex input ({e})")
    return pts, tets


def read_arcs(path):
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        fail(f"{path}: cannot parse ({e})")
    arrays = {}
    for da in root.iter("DataArray"):
        arrays[da.get("Name") or "points"] = (da.text or "").split()
    try:
        p = [float(x) for x in arrays["points"]]
        conn = [int(x) for x in arrays["connectivity"]]
        offs = [int(x) for x in arrays["offsets"]]
    except (KeyError, ValueError) as e:
        fail(f"{path}: not an arcs file written by hexex extract --edge-arcs ({e})")
    points = [tuple(p[3 * i:3 * i + 3]) for i in range(len(p) // 3)]
    lines, start = [], 0
    for end in offs:
        lines.append([points[i] for i in conn[start:end]])
        start = end
    return lines


def main():
    ap = argparse.ArgumentParser(description="Draw edge arcs over the input tet mesh.")
    ap.add_argument("hexex")
    ap.add_argument("arcs")
    ap.add_argument("out")
    ap.add_argument("--title", default="")
    ap.add_argument("--view", default="25,-60")
    ap.add_argument("--size", type=float, default=7.0)
    ap.add_argument("--dpi", type=int, default=110)
    a = ap.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection
    except ImportError:
        fail("matplotlib is missing (Debian: apt-get install python3-matplotlib)", 1)
    pts, tets = read_hexex(a.hexex)
    arcs = read_arcs(a.arcs)

    faces, edges = {}, set()
    for t in tets:
        for f in ((t[1], t[2], t[3]), (t[0], t[3], t[2]), (t[0], t[1], t[3]), (t[0], t[2], t[1])):
            key = tuple(sorted(f))
            faces[key] = None if key in faces else f
        for i in range(4):
            for j in range(i + 1, 4):
                edges.add((min(t[i], t[j]), max(t[i], t[j])))
    boundary = [[pts[v] for v in f] for f in faces.values() if f is not None]

    fig = plt.figure(figsize=(a.size, a.size))
    ax = fig.add_subplot(111, projection="3d")
    ax.add_collection3d(Poly3DCollection(boundary, facecolor=(0.8, 0.85, 0.9, 0.25), edgecolor="none"))
    ax.add_collection3d(Line3DCollection([(pts[e[0]], pts[e[1]]) for e in sorted(edges)],
                                         colors=[(0.35, 0.35, 0.35, 0.45)], linewidths=0.4))
    ax.add_collection3d(Line3DCollection(arcs, colors="tab:red", linewidths=1.3))
    ends = [line[0] for line in arcs if line] + [line[-1] for line in arcs if line]
    if ends:
        ax.scatter([p[0] for p in ends], [p[1] for p in ends], [p[2] for p in ends], s=6, c="k", depthshade=False)
    xs, ys, zs = zip(*pts)
    lo = [min(xs), min(ys), min(zs)]
    hi = [max(xs), max(ys), max(zs)]
    r = max(h - l for h, l in zip(hi, lo)) / 2
    c = [(h + l) / 2 for h, l in zip(hi, lo)]
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    elev, azim = (float(x) for x in a.view.split(","))
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()
    if a.title:
        ax.set_title(a.title)
    fig.savefig(a.out, dpi=a.dpi, bbox_inches="tight")
    return 0


if __name__ == "__main__":
    sys.exit(main())
