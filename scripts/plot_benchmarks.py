#!/usr/bin/env python3
"""Plot extraction time against input size for the cube series of extraction_benchmark.

Usage: scripts/plot_benchmarks.py RESULTS.json OUT.png

RESULTS.json is written by `extraction_benchmark --json RESULTS.json`. The plot shows,
on log-log axes, the total extraction time (extractHexMesh wall clock) of every cube case
against its input size (tets + hexes), one line per thread count, next to the published
reference points (reference HexEx and HexHex) of the same cubes. Each measured point is
labelled with its case name. Needs matplotlib (Debian: apt-get install python3-matplotlib).
"""

import json
import sys


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def cube_series(doc):
    """{threads: [(size, seconds, case), ...]} of the successful cube extractions."""
    series = {}
    for r in doc.get("results", []):
        if not r.get("case", "").startswith("cube") or r.get("status") != "ok":
            continue
        if "total_s" not in r or "tets" not in r:
            continue
        size = r["tets"] + r.get("hexes", 0)
        threads = r.get("threads_used", r.get("threads"))
        series.setdefault(threads, []).append((size, r["total_s"], r["case"]))
    for pts in series.values():
        pts.sort()
    return series


def reference_series(doc):
    """{label: [(size, seconds, case), ...]} of the published cube numbers."""
    columns = [("hexex_s", "reference HexEx"), ("hexhex_1t_s", "HexHex, 1 thread"),
               ("hexhex_2t_s", "HexHex, 2 threads")]
    series = {}
    for ref in doc.get("reference", []):
        if not ref.get("case", "").startswith("cube"):
            continue
        size = ref["tets"] + ref["hexes"]
        for key, label in columns:
            if ref.get(key) is not None:
                series.setdefault(label, []).append((size, ref[key], ref["case"]))
    for pts in series.values():
        pts.sort()
    return series


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__.split("\n\n")[1] + "\n")
        return 2
    doc = load(argv[1])
    measured = cube_series(doc)
    if not measured:
        sys.stderr.write("plot_benchmarks: no successful cube results in %s\n" % argv[1])
        return 1
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write("plot_benchmarks: matplotlib is not installed for %s; install it with\n"
                         "  apt-get install python3-matplotlib   (or: pip install matplotlib)\n"
                         % sys.executable)
        if sys.executable != "/usr/bin/python3":
            sys.stderr.write("The Debian package serves /usr/bin/python3: run "
                             "/usr/bin/python3 %s ... if it is installed there.\n" % argv[0])
        return 1

    fig, ax = plt.subplots(figsize=(7, 5))
    highest = {}  # case -> (size, seconds) of its slowest measurement, where its label goes
    for threads in sorted(measured):
        pts = measured[threads]
        xs = [p[0] for p in pts]
        ys = [p[1] for p in pts]
        ax.plot(xs, ys, "o-", label="this HexEx, %s thread%s" % (threads, "" if threads == 1 else "s"))
        for x, y, case in pts:
            if case not in highest or y > highest[case][1]:
                highest[case] = (x, y)
    for case, (x, y) in sorted(highest.items()):
        ax.annotate(case, (x, y), textcoords="offset points", xytext=(-10, 8), fontsize=8)
    if not doc.get("quick"):
        for (label, pts), marker in zip(sorted(reference_series(doc).items()), ["s", "^", "v", "D"]):
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker + "--", alpha=0.6, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("input size: tets + hexes")
    ax.set_ylabel("extraction time [s]")
    title = "Cube series, HexEx %s" % doc.get("version", "?")
    if doc.get("quick"):
        title += " (--quick inputs; reference omitted)"
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(argv[2], dpi=150)
    print("wrote %s" % argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
