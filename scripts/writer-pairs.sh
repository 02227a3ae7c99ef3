#!/usr/bin/env bash
# Paired writer timings of two builds: writer_benchmark of OLD and NEW run in turn (OLD NEW
# OLD NEW ...) on one hex mesh, best of 3 inside each run; prints per format and build the
# median over the rounds of the wall and CPU seconds, and NEW/OLD of the medians.
#
# Usage: scripts/writer-pairs.sh OLD_BUILD_DIR NEW_BUILD_DIR MESH [THREADS] [ROUNDS] [FORMATS]
#   (defaults: 2 threads, 5 rounds, faces,ovmb,ovm). MESH: any hex mesh file readHexMesh()
#   reads, e.g. the .vtu of `hexex extract cyl6.hexex -o cyl6.vtu`.
set -euo pipefail
[[ $# -ge 3 ]] || { sed -n '2,8p' "$0" >&2; exit 2; }
OLD=$1/src/Benchmarks/writer_benchmark; NEW=$2/src/Benchmarks/writer_benchmark; MESH=$3
THREADS=${4:-2}; ROUNDS=${5:-5}; FORMATS=${6:-faces,ovmb,ovm}
for b in "$OLD" "$NEW"; do [[ -x $b ]] || { echo "writer-pairs: $b not found" >&2; exit 2; }; done
OUT=$(mktemp); trap 'rm -f "$OUT"' EXIT
for ((r = 0; r < ROUNDS; ++r)); do
    "$OLD" "$MESH" "$THREADS" 3 "$FORMATS" | awk -v b=old '$3 == "s" && $4 == "wall" {print b, $1, $2, $5}' >> "$OUT"
    "$NEW" "$MESH" "$THREADS" 3 "$FORMATS" | awk -v b=new '$3 == "s" && $4 == "wall" {print b, $1, $2, $5}' >> "$OUT"
done
echo "# $MESH, $THREADS threads, $ROUNDS rounds, load $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-6s %10s %10s %10s %10s %9s %9s\n' format old_wall new_wall old_cpu new_cpu wall_x cpu_x
python3 - "$OUT" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
fmts = list(dict.fromkeys(r[1] for r in rows))
for f in fmts:
    m = {(b, k): statistics.median(float(r[2 if k == "wall" else 3]) for r in rows if r[0] == b and r[1] == f)
         for b in ("old", "new") for k in ("wall", "cpu")}
    print(f"{f:<6} {m['old','wall']:10.3f} {m['new','wall']:10.3f} {m['old','cpu']:10.3f} {m['new','cpu']:10.3f} "
          f"{m['new','wall']/m['old','wall']:9.3f} {m['new','cpu']/m['old','cpu']:9.3f}")
PY
