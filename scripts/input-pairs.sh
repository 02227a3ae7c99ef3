#!/usr/bin/env bash
# Reading and preprocessing of two builds, for a quiet machine: read_benchmark of each map,
# OLD and NEW in turn (scripts/read-pair.sh: best wall and CPU of read and preprocess at 1 and 2
# threads, new/old ratios), then the whole `hexex extract MAP -o out.ovmb --threads 2` of the
# first map paired by farm-bench (wall, CPU, peak memory), and whether the two .ovmb agree.
#
# Usage: scripts/input-pairs.sh OLD_BUILD NEW_BUILD [MAP.hexex ...]
# Environment: PAIRS=5 (alternating read_benchmark pairs), REPEAT=3 (runs per call), RUNS=7
#   (farm-bench runs per build), WORK=DIR (scratch for the .ovmb files, default a temp dir).
# Default maps: pig x2 and cube s=40 from /work/scratch/q (missing files are skipped).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OLD=${1:?usage: input-pairs.sh OLD_BUILD NEW_BUILD [MAP ...]}
NEW=${2:?usage: input-pairs.sh OLD_BUILD NEW_BUILD [MAP ...]}
shift 2
maps=("$@")
[[ ${#maps[@]} -gt 0 ]] || maps=(/work/scratch/q/pig2.hexex /work/scratch/q/c40.hexex)
for b in "$OLD" "$NEW"; do
    for x in src/Benchmarks/read_benchmark src/Tools/hexex/hexex; do
        [[ -x $b/$x ]] || { echo "input-pairs: $b/$x not found" >&2; exit 2; }
    done
done
OWN_WORK=0
if [[ -z ${WORK:-} ]]; then WORK=$(mktemp -d "${TMPDIR:-/tmp}/input-pairs.XXXXXX"); OWN_WORK=1; fi
mkdir -p "$WORK"
[[ $OWN_WORK == 1 ]] && trap 'rm -rf "$WORK"' EXIT
present=()
for m in "${maps[@]}"; do
    if [[ -f $m ]]; then present+=("$m"); else echo "# skipped (absent): $m"; fi
done
[[ ${#present[@]} -gt 0 ]] || { echo "input-pairs: no map found" >&2; exit 2; }
PAIRS=${PAIRS:-5} REPEAT=${REPEAT:-3} "$ROOT/scripts/read-pair.sh" \
    "$OLD/src/Benchmarks/read_benchmark" "$NEW/src/Benchmarks/read_benchmark" "${present[@]}"
m=${present[0]}
echo "# end to end, $(basename "$m"), 2 threads, load $(cut -d' ' -f1-3 /proc/loadavg)"
farm-bench -n "${RUNS:-7}" --timeout 600 \
    --vs "$OLD/src/Tools/hexex/hexex extract $m -o $WORK/old.ovmb --threads 2 --quiet" \
    -- "$NEW/src/Tools/hexex/hexex" extract "$m" -o "$WORK/new.ovmb" --threads 2 --quiet
cmp -s "$WORK/old.ovmb" "$WORK/new.ovmb" && echo "# .ovmb: the same bytes" || echo "# .ovmb: DIFFERENT"
