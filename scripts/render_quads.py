#!/usr/bin/env python3
"""Renders a quad mesh extracted by `hexex quad` over its input triangle mesh.

usage: render_quads.py TRIANGLES.obj QUADS.off OUT.png [--title T]

TRIANGLES.obj: the input (only `v` and `f` lines are used, `f v/vt` accepted);
QUADS.off: the output of `hexex quad ... -o QUADS.off`. Both are drawn in the xy plane:
triangles thin and grey, quads with blue edges; vertices whose number of quads differs from 4
(among interior vertices) are marked with their valence.
"""
import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402


def read_obj(path):
    pts, faces = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                pts.append((float(w[1]), float(w[2])))
            elif w[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in w[1:]])
    return pts, faces


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    assert words[0] == "OFF", path + ": not an OFF file"
    nv, nf = int(words[1]), int(words[2])
    k = 4
    pts = []
    for _ in range(nv):
        pts.append((float(words[k]), float(words[k + 1])))
        k += 3
    faces = []
    for _ in range(nf):
        n = int(words[k])
        faces.append([int(x) for x in words[k + 1:k + 1 + n]])
        k += 1 + n
    return pts, faces


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tris")
    ap.add_argument("quads")
    ap.add_argument("out")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    tp, tf = read_obj(a.tris)
    qp, qf = read_off(a.quads)
    fig, ax = plt.subplots(figsize=(6, 6), dpi=110)
    ax.add_collection(PolyCollection([[tp[i] for i in f] for f in tf], facecolors="none",
                                     edgecolors="#bbbbbb", linewidths=0.4))
    ax.add_collection(PolyCollection([[qp[i] for i in f] for f in qf], facecolors="#dbe8f7",
                                     edgecolors="#1f4e9c", linewidths=1.3, alpha=0.85))
    # Valence of every vertex (number of quads around it) and boundary edges.
    count = {}
    edges = {}
    for f in qf:
        for j, v in enumerate(f):
            count[v] = count.get(v, 0) + 1
            e = tuple(sorted((v, f[(j + 1) % len(f)])))
            edges[e] = edges.get(e, 0) + 1
    boundary = {v for e, n in edges.items() if n == 1 for v in e}
    ax.add_collection(LineCollection([[qp[a], qp[b]] for (a, b), n in edges.items() if n == 1],
                                     colors="#1f4e9c", linewidths=2.2))
    for v, n in count.items():
        if v not in boundary and n != 4:
            ax.plot(*qp[v], "o", color="#c0392b", markersize=9)
            ax.annotate(f"valence {n}", qp[v], xytext=(8, 8), textcoords="offset points", color="#c0392b",
                        fontsize=11, weight="bold")
    xs = [p[0] for p in tp]
    ys = [p[1] for p in tp]
    pad = 0.03 * max(max(xs) - min(xs), max(ys) - min(ys))
    ax.set_xlim(min(xs) - pad, max(xs) + pad)
    ax.set_ylim(min(ys) - pad, max(ys) + pad)
    ax.set_aspect("equal")
    ax.axis("off")
    if a.title:
        ax.set_title(a.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(a.out)
    print(f"render_quads.py: wrote {a.out} ({len(qf)} faces, {len(qp)} vertices)")


if __name__ == "__main__":
    main()
