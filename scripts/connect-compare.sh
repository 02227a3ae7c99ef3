#!/usr/bin/env bash
# Connect stage of two builds side by side: stage_benchmark of each map, OLD and NEW in turn,
# ROUNDS times, at 1 and 2 threads; prints the connect line (best wall and best CPU of REPS
# runs within one stage_benchmark call) and the whole extraction's line of every run. On a
# loaded machine compare the CPU columns; on a quiet one the wall columns too.
#
# Usage: scripts/connect-compare.sh OLD_BUILD NEW_BUILD [MAP.hexex ...]
# Environment: ROUNDS=3, REPS=2, THREADS="1 2".
# Default maps: pig x2, cube s=20, cylinder v6 from /work/scratch/q, and pig 1.5 seed 21 with
# its unfolded map from /work/scratch/frt-maps (missing files are skipped with a message).
set -euo pipefail
OLD=${1:?usage: connect-compare.sh OLD_BUILD NEW_BUILD [MAP ...]}
NEW=${2:?usage: connect-compare.sh OLD_BUILD NEW_BUILD [MAP ...]}
shift 2
ROUNDS=${ROUNDS:-3}
REPS=${REPS:-2}
THREADS=${THREADS:-1 2}
maps=("$@")
if [[ ${#maps[@]} -eq 0 ]]; then
    maps=(/work/scratch/q/pig2.hexex /work/scratch/q/c20.hexex /work/scratch/q/cyl6.hexex
          /work/scratch/frt-maps/pig_1.5_s21.hexex /work/scratch/frt-maps/pig_0_s21.hexex)
fi
for b in "$OLD" "$NEW"; do
    [[ -x $b/src/Benchmarks/stage_benchmark ]] || { echo "connect-compare: $b/src/Benchmarks/stage_benchmark not found" >&2; exit 2; }
done
echo "# $(date -u +%FT%TZ) load: $(cut -d' ' -f1-3 /proc/loadavg)"
for m in "${maps[@]}"; do
    if [[ ! -f $m ]]; then echo "# skipped (absent): $m"; continue; fi
    for t in $THREADS; do
        for r in $(seq "$ROUNDS"); do
            for b in "$OLD" "$NEW"; do
                out=$("$b/src/Benchmarks/stage_benchmark" "$m" "$t" "$REPS" 2>&1)
                printf '%s t%s %-4s %s | %s\n' "$(basename "$m" .hexex)" "$t" "$([[ $b == "$OLD" ]] && echo old || echo new)" \
                    "$(grep -E '^connect' <<<"$out" | tr -s ' ')" "$(grep -E '^total' <<<"$out" | tr -s ' ')"
            done
        done
    done
done
echo "# $(date -u +%FT%TZ) load: $(cut -d' ' -f1-3 /proc/loadavg)"
