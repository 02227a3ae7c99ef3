#!/usr/bin/env python3
"""Binding overhead: hexex.extract from numpy arrays vs. the C++ extraction on the same arrays.

usage: python3 python/benchmarks/bench_extract.py [--n 40 --scale 20] [--input MAP.hexex]
           [--threads 2] [--rounds 7] [--cpp-bench PATH] [--json OUT.json]

The input is the cube of `hexex generate cube --n 40 --scale 20` (384,000 tets, 8,000
hexes; the cube20 case of src/Benchmarks/ExtractionBenchmark.cc) made by
hexex.generate_cube(), or a map file given with --input. Its arrays are written as raw
files for the C++ program array_extraction_benchmark (src/Benchmarks, built by the C++
build), which times toParametrizedTetMesh() of a TetArraysView + the manifoldness check +
extractHexMesh(): what hexex.extract runs below the binding. The Python side times the
whole call hexex.extract(points, tets, params, threads=T) with time.perf_counter(): argument
checks, conversion, extraction, quality, report JSON and json.loads, result arrays.

The load-independent part of the answer: the time of each Python call spent outside the
C++ timer of that same call (report timings_s.total) is printed too.

Runs alternate (one C++ process, then Python, per round) so that a change in machine load
hits both sides alike; each side's first run in a round is a warm-up and only the second
is kept. Prints median and minimum of both and the overhead of the medians and minima.
"""

import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import hexex

REPO_ROOT = pathlib.Path(__file__).resolve().parents[2]


def cpp_run(bench, files, threads):
    """One C++ process with two repeats; returns the seconds of the second (warm) one."""
    out = subprocess.run([str(bench), *map(str, files), "--threads", str(threads), "--repeat", "2"],
                         capture_output=True, text=True, check=True).stdout
    rows = [dict(kv.split("=") for kv in line.split()) for line in out.strip().splitlines()]
    return float(rows[-1]["seconds"]), int(rows[-1]["hexes"])


def py_run(tet_map, threads):
    """Two calls of hexex.extract; returns the seconds of the second one, the seconds the C++
    side measured inside that call (report timings_s.total: conversion, extraction,
    quality, all without the GIL) and the hex count."""
    for _ in range(2):
        t0 = time.perf_counter()
        r = hexex.extract(*tet_map, threads=threads)
        seconds = time.perf_counter() - t0
    return seconds, r.report["timings_s"]["total"], len(r.hexes)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=40)
    ap.add_argument("--scale", type=int, default=20)
    ap.add_argument("--input", help="map file (.hexex/.ovm) instead of the generated cube")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--cpp-bench", default=str(REPO_ROOT / "build" / "src" / "Benchmarks" / "array_extraction_benchmark"))
    ap.add_argument("--json", help="write the numbers as JSON")
    args = ap.parse_args()

    tet_map = hexex.read_map(args.input) if args.input else hexex.generate_cube(args.n, args.scale)
    name = args.input or f"cube n={args.n} scale={args.scale}"
    cpp_times, py_times, inside = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        files = [pathlib.Path(tmp) / f for f in ("points.f64", "tets.i32", "params.f64")]
        np.ascontiguousarray(tet_map.points, dtype=np.float64).tofile(files[0])
        np.ascontiguousarray(tet_map.tets, dtype=np.int32).tofile(files[1])
        np.ascontiguousarray(tet_map.params, dtype=np.float64).tofile(files[2])
        for r in range(args.rounds):
            c, hc = cpp_run(args.cpp_bench, files, args.threads)
            p, inner, hp = py_run(tet_map, args.threads)
            if hc != hp:
                sys.exit(f"bench_extract.py: C++ made {hc} hexes, Python {hp}")
            cpp_times.append(c)
            py_times.append(p)
            inside.append(inner)
            print(f"round {r + 1}: C++ {c:.3f} s, Python {p:.3f} s (of which outside C++ {1e3 * (p - inner):.1f} ms)",
                  flush=True)
    res = {
        "input": name, "tets": int(len(tet_map.tets)), "hexes": hp, "threads": args.threads, "rounds": args.rounds,
        "cpp_s": cpp_times, "python_s": py_times,
        "cpp_median_s": statistics.median(cpp_times), "python_median_s": statistics.median(py_times),
        "cpp_min_s": min(cpp_times), "python_min_s": min(py_times),
    }
    res["overhead_median_pct"] = 100 * (res["python_median_s"] / res["cpp_median_s"] - 1)
    res["overhead_min_pct"] = 100 * (res["python_min_s"] / res["cpp_min_s"] - 1)
    # Time of the Python call spent outside the C++ timer (checks, result objects, JSON):
    # measured within each call, so machine load affects it far less than the comparison.
    res["outside_cpp_median_ms"] = 1e3 * statistics.median(p - i for p, i in zip(py_times, inside))
    res["outside_cpp_median_pct"] = 100 * statistics.median((p - i) / p for p, i in zip(py_times, inside))
    res["outside_cpp_min_ms"] = 1e3 * min(p - i for p, i in zip(py_times, inside))
    print(f"{name}: {res['tets']} tets -> {hp} hexes, {args.threads} threads, {args.rounds} rounds")
    print(f"  C++    median {res['cpp_median_s']:.3f} s  min {res['cpp_min_s']:.3f} s")
    print(f"  Python median {res['python_median_s']:.3f} s  min {res['python_min_s']:.3f} s")
    print(f"  overhead: median {res['overhead_median_pct']:+.1f} %, min {res['overhead_min_pct']:+.1f} %")
    print(f"  time of the Python call outside the C++ timer: median {res['outside_cpp_median_ms']:.1f} ms "
          f"({res['outside_cpp_median_pct']:.2f} %), min {res['outside_cpp_min_ms']:.1f} ms")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(res, indent=2) + "\n")


if __name__ == "__main__":
    main()
