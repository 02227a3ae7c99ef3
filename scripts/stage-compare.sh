#!/usr/bin/env bash
# Stages of two builds side by side: stage_benchmark of each map, OLD and NEW in turn, ROUNDS
# times, at 1 and 2 threads; prints the lines of the chosen stages (best wall and best CPU of
# REPS runs within one stage_benchmark call) and the whole extraction's line. On a loaded
# machine compare the CPU columns; on a quiet one the wall columns too. stage_benchmark
# extracts through the const overload, so its preprocess includes the copy of the corner
# parameters that `hexex extract` does not make.
#
# Usage: scripts/stage-compare.sh OLD_BUILD NEW_BUILD [MAP.hexex ...]
# Environment: ROUNDS=3, REPS=2, THREADS="1 2", STAGES="preprocess darts connect" (any of
#   preprocess darts connect postprocess vertices assemble).
# Default maps: pig x2, cube s=20, cylinder v6 from /work/scratch/q, and pig 1.5 seed 21 with
# its unfolded map from /work/scratch/frt-maps (missing files are skipped with a message);
# cube s=40 is `hexex generate cube --n 80 --scale 40`.
set -euo pipefail
OLD=${1:?usage: stage-compare.sh OLD_BUILD NEW_BUILD [MAP ...]}
NEW=${2:?usage: stage-compare.sh OLD_BUILD NEW_BUILD [MAP ...]}
shift 2
ROUNDS=${ROUNDS:-3}
REPS=${REPS:-2}
THREADS=${THREADS:-1 2}
STAGES=${STAGES:-preprocess darts connect}
maps=("$@")
if [[ ${#maps[@]} -eq 0 ]]; then
    maps=(/work/scratch/q/pig2.hexex /work/scratch/q/c20.hexex /work/scratch/q/cyl6.hexex
          /work/scratch/frt-maps/pig_1.5_s21.hexex /work/scratch/frt-maps/pig_0_s21.hexex)
fi
for b in "$OLD" "$NEW"; do
    [[ -x $b/src/Benchmarks/stage_benchmark ]] || { echo "stage-compare: $b/src/Benchmarks/stage_benchmark not found" >&2; exit 2; }
done
pattern="^($(tr ' ' '|' <<<"$STAGES")|total) "
echo "# $(date -u +%FT%TZ) load: $(cut -d' ' -f1-3 /proc/loadavg)"
for m in "${maps[@]}"; do
    if [[ ! -f $m ]]; then echo "# skipped (absent): $m"; continue; fi
    for t in $THREADS; do
        for r in $(seq "$ROUNDS"); do
            for b in "$OLD" "$NEW"; do
                out=$("$b/src/Benchmarks/stage_benchmark" "$m" "$t" "$REPS" 2>&1)
                printf '%s t%s %-4s %s\n' "$(basename "$m" .hexex)" "$t" "$([[ $b == "$OLD" ]] && echo old || echo new)" \
                    "$(grep -E "$pattern" <<<"$out" | tr -s ' ' | paste -sd'|')"
            done
        done
    done
done
echo "# $(date -u +%FT%TZ) load: $(cut -d' ' -f1-3 /proc/loadavg)"
