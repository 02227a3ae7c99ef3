#!/usr/bin/env bash
# Run time of folded maps against the same maps without folds (issue 35's target: at most 2x).
# For each case the map built from a published hex mesh (`hexex generate from-hex`) with
# `--perturb A --seed S` and the same mesh with `--perturb 0 --seed S` are extracted with
# `hexex extract --threads T`, alternating, RUNS times each; printed per case and thread
# count: median CPU seconds (user + sys) and wall seconds of each, and the ratios
# folded / unfolded of the medians. With two build directories, each case runs with both
# builds in turn (old, new, old, new, ...) and the table has one line per build.
#
# Usage: scripts/fold-run-time.sh BUILD_DIR [BUILD_DIR2]
# Environment: RUNS=3, THREADS="1 2", HEXEX_SHARED=DIR (default <repo>/../shared),
#   WORK=DIR (scratch for the maps, default a temp dir; maps already there are reused),
#   CASES="pig 0.8 7,pig 1.0 1,..." (mesh amplitude seed; default the eight cases below).
# Without the shared data it prints a note and exits 0.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
[[ $# -ge 1 ]] || { echo "usage: $0 BUILD_DIR [BUILD_DIR2]" >&2; exit 2; }
BUILDS=("$@")
SHARED=${HEXEX_SHARED:-$ROOT/../shared}
RUNS=${RUNS:-3}
THREADS=${THREADS:-1 2}
CASES=${CASES:-pig 0.8 7,pig 1.0 1,pig 1.2 1,pig 1.2 29,pig 1.5 16,pig 1.5 21,pig 1.5 29,cfpc16 1.5 3}
if [[ ! -d $SHARED/data/hexmeshes ]]; then
    echo "fold-run-time: $SHARED/data/hexmeshes not found: nothing to measure"
    exit 0
fi
for b in "${BUILDS[@]}"; do
    [[ -x $b/src/Tools/hexex/hexex ]] || { echo "fold-run-time: $b/src/Tools/hexex/hexex not found" >&2; exit 2; }
done
OWN_WORK=0
if [[ -z ${WORK:-} ]]; then WORK=$(mktemp -d "${TMPDIR:-/tmp}/fold-run-time.XXXXXX"); OWN_WORK=1; fi
mkdir -p "$WORK"
[[ $OWN_WORK == 1 ]] && trap 'rm -rf "$WORK"' EXIT
GEN=${BUILDS[0]}/src/Tools/hexex/hexex
for m in sss19_pig_in:pig cfpc16_hollow8:cfpc16; do
    [[ -f $WORK/${m#*:}.vtk ]] || xz -dc "$SHARED/data/hexmeshes/${m%%:*}.vtk.xz" > "$WORK/${m#*:}.vtk"
done
map() {  # mesh amplitude seed -> path of the map (generated once)
    local f=$WORK/$1_$2_s$3.hexex
    [[ -f $f ]] || "$GEN" generate from-hex "$WORK/$1.vtk" --perturb "$2" --seed "$3" --quiet -o "$f"
    echo "$f"
}
# One extraction: prints "cpu wall" (seconds).
run() {
    /usr/bin/time -o "$WORK/time.txt" -f "%U %S %e" "$1/src/Tools/hexex/hexex" extract "$2" -o "$WORK/out.ovmb" --threads "$3" --quiet \
        > /dev/null 2>&1 || true
    awk '{printf "%.3f %.3f\n", $1 + $2, $3}' "$WORK/time.txt"
}
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
printf '%-16s %2s %-8s %10s %10s %7s %10s %10s %7s\n' case T build "cpu unf" "cpu fold" "ratio" "wall unf" "wall fold" "ratio"
IFS=, read -r -a cases <<< "$CASES"
for c in "${cases[@]}"; do
    read -r mesh a seed <<< "$c"
    folded=$(map "$mesh" "$a" "$seed")
    plain=$(map "$mesh" 0 "$seed")
    for t in $THREADS; do
        declare -A cu=() cf=() wu=() wf=()
        for ((r = 0; r < RUNS; ++r)); do
            for k in "${!BUILDS[@]}"; do
                read -r x y <<< "$(run "${BUILDS[$k]}" "$plain" "$t")"; cu[$k]+="$x "; wu[$k]+="$y "
                read -r x y <<< "$(run "${BUILDS[$k]}" "$folded" "$t")"; cf[$k]+="$x "; wf[$k]+="$y "
            done
        done
        for k in "${!BUILDS[@]}"; do
            mcu=$(tr ' ' '\n' <<< "${cu[$k]}" | grep . | median); mcf=$(tr ' ' '\n' <<< "${cf[$k]}" | grep . | median)
            mwu=$(tr ' ' '\n' <<< "${wu[$k]}" | grep . | median); mwf=$(tr ' ' '\n' <<< "${wf[$k]}" | grep . | median)
            printf '%-16s %2s %-8s %10.2f %10.2f %6.2fx %10.2f %10.2f %6.2fx\n' "$mesh $a s$seed" "$t" "$((k + 1))" \
                "$mcu" "$mcf" "$(awk -v a="$mcf" -v b="$mcu" 'BEGIN {print a / b}')" \
                "$mwu" "$mwf" "$(awk -v a="$mwf" -v b="$mwu" 'BEGIN {print a / b}')"
        done
        unset cu cf wu wf
    done
done
echo "# builds: $(for k in "${!BUILDS[@]}"; do printf '%d=%s ' $((k + 1)) "${BUILDS[$k]}"; done); runs per median: $RUNS; load at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
