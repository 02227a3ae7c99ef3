#!/usr/bin/env python3
"""Renders the hexes that the dart reconnection formed, in the extracted mesh, with their
neighbours and the singular edges near them (Documentation/algorithm.md, "Reconnecting the
darts of broken cells").

usage: render_reconnection.py SOURCE.vtk OUT.vtk HEX [HEX ...] -o OUT.png [--title T]

SOURCE.vtk: the hex mesh the map was built from (`hexex generate from-hex`); OUT.vtk: the
mesh `hexex extract` wrote from the folded map; HEX: source hex numbers of the reconnected
cells. Each is looked up in OUT.vtk by its eight vertex positions (the extraction puts every
vertex at its source position; a missing hex is an error), so the picture shows the output,
not the source. Drawn: the reconnected hexes (orange), the output hexes sharing a vertex with
them (grey, transparent) along an edge, interior edges of the reconnected hexes
whose valence is not 4 (red, labelled with the valence).
"""
import argparse
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]


def read_vtk(path):
    """Points and hexes of a legacy ASCII VTK unstructured grid (old CELLS or OFFSETS/CONNECTIVITY)."""
    words = open(path).read().split()
    i = words.index("POINTS")
    n = int(words[i + 1])
    pts = [tuple(float(w) for w in words[i + 3 + 3 * k:i + 6 + 3 * k]) for k in range(n)]
    c = words.index("CELLS")
    ncells = int(words[c + 1])
    if words[c + 3] == "OFFSETS":
        o = c + 5
        offsets = [int(w) for w in words[o:o + ncells]]
        k = words.index("CONNECTIVITY", o)
        conn = [int(w) for w in words[k + 2:k + 2 + offsets[-1]]]
        cells = [conn[offsets[j]:offsets[j + 1]] for j in range(ncells - 1)]
    else:
        cells, p = [], c + 3
        for _ in range(ncells):
            m = int(words[p])
            cells.append([int(w) for w in words[p + 1:p + 1 + m]])
            p += m + 1
    return pts, [h for h in cells if len(h) == 8]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("source")
    ap.add_argument("out")
    ap.add_argument("hexes", type=int, nargs="+")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    spts, shex = read_vtk(a.source)
    opts, ohex = read_vtk(a.out)
    key = {tuple(round(x, 9) for x in p): v for v, p in enumerate(opts)}
    byverts = {tuple(sorted(h)): j for j, h in enumerate(ohex)}
    found = []
    for h in a.hexes:
        verts = [key.get(tuple(round(x, 9) for x in spts[v])) for v in shex[h]]
        if None in verts or tuple(sorted(verts)) not in byverts:
            raise SystemExit(f"source hex {h} is not in {a.out}")
        found.append(byverts[tuple(sorted(verts))])
    core = set(v for j in found for v in ohex[j])
    near = [j for j, h in enumerate(ohex) if j not in found and len(core & set(h)) >= 2]
    # Edge valences of the output (interior edges: every quad around them shared by two hexes).
    edge_hexes, quad_count = defaultdict(int), defaultdict(int)
    for h in ohex:
        for e in EDGES:
            edge_hexes[tuple(sorted((h[e[0]], h[e[1]])))] += 1
        for f in FACES:
            quad_count[tuple(sorted(h[i] for i in f))] += 1
    boundary_edges = set()
    for h in ohex:
        for f in FACES:
            if quad_count[tuple(sorted(h[i] for i in f))] == 1:
                for k in range(4):
                    boundary_edges.add(tuple(sorted((h[f[k]], h[f[(k + 1) % 4]]))))
    region = set(v for j in found + near for v in ohex[j])
    singular = [(e, n) for e, n in edge_hexes.items()
                if n != 4 and e[0] in core and e[1] in core and e not in boundary_edges]
    fig = plt.figure(figsize=(4.2, 4.2), dpi=110)
    ax = fig.add_subplot(111, projection="3d")
    quads = lambda js: [[opts[ohex[j][i]] for i in f] for j in js for f in FACES]  # noqa: E731
    ax.add_collection3d(Poly3DCollection(quads(near), facecolor=(0.7, 0.7, 0.7, 0.08), edgecolor=(0.3, 0.3, 0.3, 0.35), linewidth=0.4))
    ax.add_collection3d(Poly3DCollection(quads(found), facecolor=(1.0, 0.55, 0.1, 0.45), edgecolor="k", linewidth=0.9))
    if singular:
        ax.add_collection3d(Line3DCollection([[opts[e[0]], opts[e[1]]] for e, _ in singular], colors="red", linewidths=2.5))
        for e, n in singular:
            m = [(opts[e[0]][k] + opts[e[1]][k]) / 2 for k in range(3)]
            ax.text(m[0], m[1], m[2], str(n), color="red", fontsize=9)
    xs = [opts[v] for v in core]  # zoom on the reconnected hexes, the neighbours cut by the view
    r = 0.85 * max(max(p[j] for p in xs) - min(p[j] for p in xs) for j in range(3))
    for k, setlim in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
        c = (min(p[k] for p in xs) + max(p[k] for p in xs)) / 2
        setlim(c - r, c + r)
    ax.view_init(elev=25, azim=-60)
    ax.set_axis_off()
    if a.title:
        ax.set_title(a.title, fontsize=9)
    fig.tight_layout()
    fig.savefig(a.output)
    print(f"{a.output}: {len(found)} reconnected hexes (output {found}), {len(near)} neighbours, "
          f"{len(singular)} interior edges of valence != 4 ({sorted(n for _, n in singular)})")


if __name__ == "__main__":
    main()
