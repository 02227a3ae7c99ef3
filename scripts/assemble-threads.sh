#!/usr/bin/env bash
# The vertices and assemble stages at 1 and 2 threads, old build against new (issue 36), for a
# quiet machine: stage_benchmark side by side (scripts/stage-compare.sh: best wall and best CPU
# of REPS runs per call, ROUNDS alternating rounds), then `hexex extract MAP -o out.ovmb
# --threads 2 --quiet` paired under farm-bench (medians of RUNS; CPU, wall, peak memory).
#
# Usage: scripts/assemble-threads.sh OLD_BUILD NEW_BUILD [MAP.hexex ...]
# Environment: ROUNDS=3, REPS=3, RUNS=5, WORK=DIR (scratch for the .ovmb files, default a temp dir).
# Default maps: cylinder v6 and pig x2 from /work/scratch/q (missing files are skipped).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OLD=${1:?usage: assemble-threads.sh OLD_BUILD NEW_BUILD [MAP ...]}
NEW=${2:?usage: assemble-threads.sh OLD_BUILD NEW_BUILD [MAP ...]}
shift 2
maps=("$@")
[[ ${#maps[@]} -eq 0 ]] && maps=(/work/scratch/q/cyl6.hexex /work/scratch/q/pig2.hexex)
RUNS=${RUNS:-5}
WORK=${WORK:-$(mktemp -d "${TMPDIR:-/tmp}/assemble-threads.XXXXXX")}
mkdir -p "$WORK"
ROUNDS=${ROUNDS:-3} REPS=${REPS:-3} THREADS="1 2" STAGES="vertices assemble" \
    "$ROOT/scripts/stage-compare.sh" "$OLD" "$NEW" "${maps[@]}"
command -v farm-bench > /dev/null || { echo "# farm-bench not found: extract timings skipped"; exit 0; }
for m in "${maps[@]}"; do
    [[ -f $m ]] || continue
    echo "# hexex extract $(basename "$m") --threads 2, A = new, B = old"
    farm-bench -n "$RUNS" --timeout 600 \
        --vs "$OLD/src/Tools/hexex/hexex extract $m -o $WORK/old.ovmb --threads 2 --quiet" \
        -- "$NEW/src/Tools/hexex/hexex" extract "$m" -o "$WORK/new.ovmb" --threads 2 --quiet 2>&1 |
        grep -E "cpu s|wall s|peak MiB|A/B"
    cmp -s "$WORK/old.ovmb" "$WORK/new.ovmb" && echo "# outputs identical" || echo "# OUTPUTS DIFFER"
done
