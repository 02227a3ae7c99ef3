#!/usr/bin/env bash
# Reading and preprocessing, old build against new: runs two read_benchmark binaries in turn
# (old, new, old, new, ...) on each file at 1 and 2 threads and prints, per file and thread
# count, each binary's best wall and CPU time of the read (parse, orientation, adjacency,
# manifold check) and of the preprocess stage over all its runs, and new/old ratios.
#
# Usage: scripts/read-pair.sh OLD_READ_BENCHMARK NEW_READ_BENCHMARK FILE.hexex...
# Environment: PAIRS=3 (alternating pairs), REPEAT=3 (runs inside each read_benchmark call).
# On a shared machine only the CPU columns are comparable; wall ratios need a quiet machine.
set -euo pipefail
[[ $# -ge 3 ]] || { echo "usage: $0 OLD_READ_BENCHMARK NEW_READ_BENCHMARK FILE.hexex..." >&2; exit 2; }
OLD=$1 NEW=$2
shift 2
PAIRS=${PAIRS:-3}
REPEAT=${REPEAT:-3}
for x in "$OLD" "$NEW"; do [[ -x $x ]] || { echo "read-pair: $x not found" >&2; exit 2; }; done
echo "read-pair, $PAIRS pairs x best of $REPEAT, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for f in "$@"; do
    for t in 1 2; do
        out=$(for ((p = 0; p < PAIRS; ++p)); do
            "$OLD" "$f" "$t" "$REPEAT" | awk -v b=old '$1=="read"||$1=="preprocess"{print b, $1, $2, $3}'
            "$NEW" "$f" "$t" "$REPEAT" | awk -v b=new '$1=="read"||$1=="preprocess"{print b, $1, $2, $3}'
        done)
        echo "$out" | python3 -c '
import sys
best = {}
for line in sys.stdin:
    b, step, wall, cpu = line.split()
    w, c = best.get((b, step), (1e300, 1e300))
    best[(b, step)] = (min(w, float(wall)), min(c, float(cpu)))
f, t = sys.argv[1], sys.argv[2]
print(f"{f}, {t} thread(s):      old wall / cpu      new wall / cpu      new/old wall / cpu")
for step in ("read", "preprocess"):
    ow, oc = best[("old", step)]
    nw, nc = best[("new", step)]
    rw = f"{nw / ow:.2f}" if ow > 0 else "-"
    rc = f"{nc / oc:.2f}" if oc > 0 else "-"
    print(f"  {step:<12} {ow:8.3f} / {oc:6.3f}    {nw:8.3f} / {nc:6.3f}    {rw} / {rc}")
' "$(basename "$f")" "$t"
    done
done
