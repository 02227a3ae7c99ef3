#!/usr/bin/env bash
# The postprocess and vertices stages of folded maps, two builds alternating (issue 35): for
# each map and thread count, `hexex extract MAP -o OUT.ovmb --threads T --report R.json` with
# the old and the new build in turn, RUNS times each; printed per map, thread count and build:
# the medians of the report's postprocess and vertices seconds (wall), of the whole
# extraction's CPU (user + sys) and wall seconds, and the peak RSS, and whether the two
# builds wrote the same bytes. The postprocess stage runs partly on a second thread (the
# annihilation's phase-by-phase retry beside the first pass, algorithm.md), so its wall time
# means something only on a quiet machine.
#
# Usage: scripts/postprocess-pairs.sh OLD_BUILD NEW_BUILD MAP.hexex [MAP.hexex ...]
# Environment: RUNS=5, THREADS="1 2", WORK=DIR (scratch, default a temp dir).
# Example: scripts/postprocess-pairs.sh /work/build-s47-base build /work/scratch/frt-maps/pig_1.5_s21.hexex
set -euo pipefail
[[ $# -ge 3 ]] || { echo "usage: $0 OLD_BUILD NEW_BUILD MAP.hexex [MAP.hexex ...]" >&2; exit 2; }
OLD=$1
NEW=$2
shift 2
RUNS=${RUNS:-5}
THREADS=${THREADS:-1 2}
for b in "$OLD" "$NEW"; do
    [[ -x $b/src/Tools/hexex/hexex ]] || { echo "postprocess-pairs: $b/src/Tools/hexex/hexex not found" >&2; exit 2; }
done
OWN_WORK=0
if [[ -z ${WORK:-} ]]; then WORK=$(mktemp -d "${TMPDIR:-/tmp}/postprocess-pairs.XXXXXX"); OWN_WORK=1; fi
mkdir -p "$WORK"
[[ $OWN_WORK == 1 ]] && trap 'rm -rf "$WORK"' EXIT
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
# One run: prints "postprocess vertices cpu wall peakKB".
run() {  # build map threads out
    /usr/bin/time -o "$WORK/time.txt" -f "%U %S %e %M" "$1/src/Tools/hexex/hexex" extract "$2" -o "$4" --threads "$3" \
        --report "$WORK/r.json" --quiet > /dev/null 2>&1
    python3 - "$WORK/r.json" "$WORK/time.txt" <<'EOF'
import json, sys
t = json.load(open(sys.argv[1]))["timings_s"]
u, s, e, m = open(sys.argv[2]).read().split()[:4]
print("%.3f %.3f %.3f %.3f %s" % (t["postprocess"], t["vertices"], float(u) + float(s), float(e), m))
EOF
}
printf '%-22s %2s %-4s %9s %9s %8s %8s %9s %5s\n' map T build postproc vertices cpu wall peakKB same
for map in "$@"; do
    for t in $THREADS; do
        declare -A col=()
        same=yes
        for ((r = 0; r < RUNS; ++r)); do
            read -r a b c d e <<< "$(run "$OLD" "$map" "$t" "$WORK/old.ovmb")"
            col[old0]+="$a "; col[old1]+="$b "; col[old2]+="$c "; col[old3]+="$d "; col[old4]+="$e "
            read -r a b c d e <<< "$(run "$NEW" "$map" "$t" "$WORK/new.ovmb")"
            col[new0]+="$a "; col[new1]+="$b "; col[new2]+="$c "; col[new3]+="$d "; col[new4]+="$e "
            cmp -s "$WORK/old.ovmb" "$WORK/new.ovmb" || same=NO
        done
        for k in old new; do
            printf '%-22s %2s %-4s' "$(basename "$map" .hexex)" "$t" "$k"
            for i in 0 1 2 3; do printf ' %9.3f' "$(tr ' ' '\n' <<< "${col[$k$i]}" | grep . | median)"; done
            printf ' %9s %5s\n' "$(tr ' ' '\n' <<< "${col[${k}4]}" | grep . | median)" "$same"
        done
        unset col
    done
done
