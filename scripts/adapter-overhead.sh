#!/usr/bin/env bash
# Read/write overhead of the framework-native adapter calls against the built-in kernel
# (issue 34): runs src/Benchmarks/adapter_benchmark for every CASE x PATH, REPEAT times,
# the paths alternating, one process per measurement, and prints the medians (min-max) of
# the stages in CPU seconds of the process (cpu_copy_s: read into the built-in kernel
# including the adjacency, for builtin the adjacency alone; cpu_extract_s; cpu_write_s:
# writing into the user's mesh), the wall total, the peak (/usr/bin/time -v), and the
# overheads relative to the builtin extraction: read overhead (adapter copy - builtin copy) /
# builtin extract, and total overhead ((adapter copy + extract) - (builtin copy + extract)) /
# builtin extract (the one-call overloads hand the read parameters to the pipeline as its
# working copy, which the builtin extraction copies: that copy moved into the read).
# Path ovm-native-split shows the writing as HexEx's part + OpenVolumeMesh's bottom-up
# incidence rebuild (vertex lists, edge lists, face incidences with OpenVolumeMesh's ordering
# of the halffaces around every edge); ovm-native-vf writes into a hex mesh without edge
# incidences; ovm-native-fe turns the face incidences on before the edge lists,
# ovm-write-inc and ovm-write-ovm write with the incidences on from the start (see
# AdapterBenchmark.cc). The cpu write column ends with the whole writing in units of the
# builtin extraction's CPU.
#
#   BENCH=build/src/Benchmarks/adapter_benchmark REPEAT=3 CASES="cube20 cube40 cylinder6" \
#   PATHS="builtin ovm-native lcc-native" scripts/adapter-overhead.sh
#
# With OLD=another adapter_benchmark binary, every adapter path also runs with OLD in the same
# round, right before BENCH's run (rows "PATH (old)"), for a paired before/after; the
# builtin path runs from BENCH only. The wall columns (wall read, wall read+extract
# overhead) are what the adapters' threads shorten; the CPU columns add all threads.
set -euo pipefail
BENCH=${BENCH:-build/src/Benchmarks/adapter_benchmark}
OLD=${OLD:-}
REPEAT=${REPEAT:-3}
CASES=${CASES:-"cube20 cube40 cylinder6"}
PATHS=${PATHS:-"builtin ovm-native lcc-native"}
out=$(mktemp)
trap 'rm -f "$out" "$out.time"' EXIT
for r in $(seq "$REPEAT"); do
  for c in $CASES; do
    for p in $PATHS; do
      runs="$BENCH"
      if [ -n "$OLD" ] && [ "$p" != builtin ] && [ "$p" != builtin-provenance ]; then runs="$OLD $BENCH"; fi
      for b in $runs; do
        line=$(/usr/bin/time -v -o "$out.time" "$b" "$c" "$p")
        rss=$(awk -F: '/Maximum resident set size/ {gsub(/ /, "", $2); print $2}' "$out.time")
        [ "$b" = "$OLD" ] && [ "$b" != "$BENCH" ] && line=$(echo "$line" | sed "s/path=$p /path=$p(old) /")
        echo "$line rss_kb=$rss load=$(cut -d' ' -f1 /proc/loadavg)" >> "$out"
      done
    done
  done
done
python3 - "$out" <<'PY'
import statistics, sys
rows = {}
for line in open(sys.argv[1]):
    kv = dict(x.split("=", 1) for x in line.split())
    rows.setdefault((kv["case"], kv["path"]), []).append(kv)
def med(key, runs):
    v = sorted(float(r[key]) for r in runs)
    return statistics.median(v), v[0], v[-1]
def fmt(t):
    return f"{t[0]:.2f} ({t[1]:.2f}-{t[2]:.2f})"
print("| case / path | cpu read | cpu extract | cpu write | wall read | wall total | peak MB | input MB | read overhead | read+extract overhead | wall read+extract overhead |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for (c, p), runs in rows.items():
    base = rows.get((c, "builtin"))
    over = total = wtotal = ""
    if base and p != "builtin":
        bx = med('cpu_extract_s', base)[0]
        over = f"{100 * (med('cpu_copy_s', runs)[0] - med('cpu_copy_s', base)[0]) / bx:+.0f} %"
        both = lambda rs: statistics.median(float(r['cpu_copy_s']) + float(r['cpu_extract_s']) for r in rs)
        total = f"{100 * (both(runs) - both(base)) / bx:+.0f} %"
        wboth = lambda rs: statistics.median(float(r['copy_s']) + float(r['extract_s']) for r in rs)
        wtotal = f"{100 * (wboth(runs) - wboth(base)) / med('extract_s', base)[0]:+.0f} %"
    peak = statistics.median(float(r["rss_kb"]) / 1024 for r in runs)
    # ovm-native-split: HexEx's writing, then OpenVolumeMesh's incidence rebuild
    inc = f" + {fmt(med('cpu_incidences_s', runs))} OVM incidences" if float(runs[0].get("cpu_incidences_s", 0)) > 0 else ""
    if inc and "cpu_inc_face_s" in runs[0] and p.endswith("-fe"):  # face incidences first, the ordering with the edge lists
        inc += f" (vertex {med('cpu_inc_vertex_s', runs)[0]:.2f}, face {med('cpu_inc_face_s', runs)[0]:.2f}, edge + ordering {med('cpu_inc_edge_s', runs)[0]:.2f})"
    elif inc and "cpu_inc_face_s" in runs[0]:  # vertex lists, edge lists, face incidences with the ordering around edges
        inc += f" (vertex {med('cpu_inc_vertex_s', runs)[0]:.2f}, edge {med('cpu_inc_edge_s', runs)[0]:.2f}, face + ordering {med('cpu_inc_face_s', runs)[0]:.2f})"
    # the whole writing (HexEx's part and OpenVolumeMesh's incidences) in units of the builtin extraction's CPU
    if base and p != "builtin" and float(runs[0].get("cpu_write_s", 0)) > 0:
        wr = statistics.median(float(r['cpu_write_s']) + float(r.get('cpu_incidences_s', 0)) for r in runs)
        inc += f" = {wr / med('cpu_extract_s', base)[0]:.1f}x extraction"
    print(f"| {c} {p} | {fmt(med('cpu_copy_s', runs))} | {fmt(med('cpu_extract_s', runs))} | "
          f"{fmt(med('cpu_write_s', runs))}{inc} | {fmt(med('copy_s', runs))} | {fmt(med('total_s', runs))} | {peak:.0f} | "
          f"{runs[0]['input_mb']} | {over} | {total} | {wtotal} |")
loads = sorted(float(r["load"]) for rs in rows.values() for r in rs if "load" in r)
if loads:
    print(f"\nload average (1 min) at the end of the runs: {loads[0]:.1f}-{loads[-1]:.1f}")
PY
