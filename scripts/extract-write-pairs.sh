#!/usr/bin/env bash
# Paired end-to-end timings of two builds: `hexex extract MAP -o OUT.EXT --threads T --report R`
# of OLD and NEW in turn (OLD NEW OLD NEW ...); prints per build the median over the rounds of
# the report's stage times (assemble, write, the extraction = preprocess..assemble, total),
# the process CPU (user + system, /usr/bin/time) and peak memory, NEW/OLD of the medians, the
# writer's time against the extraction's, and whether the outputs are the same bytes.
#
# Usage: scripts/extract-write-pairs.sh OLD_BUILD_DIR NEW_BUILD_DIR MAP [THREADS] [ROUNDS] [EXT]
#   (defaults: 2 threads, 5 rounds, ovmb). Run it on a quiet machine for wall times.
set -euo pipefail
[[ $# -ge 3 ]] || { sed -n '2,9p' "$0" >&2; exit 2; }
OLD=$1/src/Tools/hexex/hexex; NEW=$2/src/Tools/hexex/hexex; MAP=$3
THREADS=${4:-2}; ROUNDS=${5:-5}; EXT=${6:-ovmb}
for b in "$OLD" "$NEW"; do [[ -x $b ]] || { echo "extract-write-pairs: $b not found" >&2; exit 2; }; done
DIR=$(mktemp -d); trap 'rm -rf "$DIR"' EXIT
for ((r = 0; r < ROUNDS; ++r)); do
    for b in old new; do
        bin=$OLD; [[ $b == new ]] && bin=$NEW
        /usr/bin/time -f "%U %S %M" -o "$DIR/time" "$bin" extract "$MAP" -o "$DIR/$b.$EXT" --threads "$THREADS" --quiet \
            --report "$DIR/$b.json" || true
        python3 - "$DIR/$b.json" "$DIR/time" "$b" >> "$DIR/rows" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))["timings_s"]
u, s, m = open(sys.argv[2]).read().split()[-3:]
ext = sum(t.get(k, 0) for k in ("preprocess", "darts", "connect", "postprocess", "vertices", "assemble"))
print(sys.argv[3], t["assemble"], t["write"], ext, t["total"], float(u) + float(s), int(m) / 1024)
PY
    done
done
echo "# $MAP -o .$EXT, $THREADS threads, $ROUNDS rounds, load $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$DIR/rows" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
names = ["assemble_s", "write_s", "extraction_s", "total_s", "cpu_s", "peak_MiB"]
med = {(b, i): statistics.median(float(r[i + 1]) for r in rows if r[0] == b) for b in ("old", "new") for i in range(6)}
print(f"{'':14}{'old':>10}{'new':>10}{'new/old':>10}")
for i, n in enumerate(names):
    print(f"{n:14}{med['old', i]:10.3f}{med['new', i]:10.3f}{med['new', i] / med['old', i]:10.3f}")
for b in ("old", "new"):
    print(f"write/extraction {b}: {med[b, 1] / med[b, 2]:.3f}")
PY
cmp -s "$DIR/old.$EXT" "$DIR/new.$EXT" && echo "outputs: same bytes" || echo "outputs: DIFFERENT"
