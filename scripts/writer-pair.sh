#!/usr/bin/env bash
# Two builds' writers side by side on one hex mesh: writer_benchmark of OLD and NEW run in turn
# (OLD NEW OLD NEW ...), PAIRS times, 2 threads; prints every run and then, per format, the best
# wall time of each build with the CPU time of that run and the ratio NEW/OLD.
#
# Usage: scripts/writer-pair.sh OLD_BUILD NEW_BUILD MESH [PAIRS] [FORMATS] [DIR]
#   MESH     a hex mesh writer_benchmark reads (e.g. the .vtu of `hexex extract`)
#   PAIRS    runs of each build (default 3), each writer_benchmark run is best of 2
#   FORMATS  comma-separated list for writer_benchmark (default faces,ovm,ovmb)
#   DIR      write files into DIR as hexex does (default: into memory)
# On a shared machine only the CPU columns and the ratios of alternating runs mean much.
set -euo pipefail
[[ $# -ge 3 ]] || { echo "usage: $0 OLD_BUILD NEW_BUILD MESH [PAIRS] [FORMATS] [DIR]" >&2; exit 2; }
OLD=$1/src/Benchmarks/writer_benchmark; NEW=$2/src/Benchmarks/writer_benchmark; MESH=$3
PAIRS=${4:-3}; FORMATS=${5:-faces,ovm,ovmb}; DIR=${6:-}
for x in "$OLD" "$NEW"; do [[ -x $x ]] || { echo "writer-pair: $x not found (build writer_benchmark)" >&2; exit 2; }; done
TMP=$(mktemp -d "${TMPDIR:-/tmp}/writer-pair.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
WHERE="into memory"; [[ -n $DIR ]] && WHERE="files in $DIR"
echo "writer-pair: $PAIRS pairs, $(date -u "+%Y-%m-%d %H:%M UTC"), load $(cut -d" " -f1-3 /proc/loadavg), $WHERE"
for ((i = 0; i < PAIRS; ++i)); do
    for b in old new; do
        exe=$OLD; [[ $b == new ]] && exe=$NEW
        "$exe" "$MESH" 2 2 "$FORMATS" ${DIR:+"$DIR"} | tail -n +2 | awk -v b=$b '{print b, $1, $2, $5}' | tee -a "$TMP/runs.txt"
    done
done
python3 - "$TMP/runs.txt" <<'EOF'
import sys
best = {}
for line in open(sys.argv[1]):
    b, fmt, wall, cpu = line.split()
    key = (fmt, b)
    if key not in best or float(wall) < best[key][0]:
        best[key] = (float(wall), float(cpu))
print("format   old wall / cpu     new wall / cpu     new/old wall   new/old cpu")
for fmt in dict.fromkeys(k[0] for k in best):
    o, n = best.get((fmt, "old")), best.get((fmt, "new"))
    if o and n:
        print(f"{fmt:<8} {o[0]:7.3f} / {o[1]:6.3f}   {n[0]:7.3f} / {n[1]:6.3f}   {n[0] / o[0]:8.2f}x     {n[1] / o[1]:8.2f}x")
EOF
