#!/usr/bin/env bash
# Issue 35's perturbed singular cylinders: the generated cylinders of valence 3, 5 and 6
# (radius 3, height 3: 81, 135 and 162 hexes) with `hexex perturb -a A` for A = 1.5 and 2.0,
# seeds 1-5, extracted with `hexex extract`; one line per case (valence, a, seed, hexes,
# non-hex cells, the report's valid_all_hex, `hexex validate` of the written mesh, broken
# cells after the annihilation, remaining anti darts, flipped tets) and the count of cases
# that are valid all-hex with the exact hex count (report and written mesh).
#
# Usage: scripts/fold-cylinders.sh [BUILD_DIR]      (default BUILD_DIR: <repo>/build)
# Environment: THREADS=2, A="1.5 2.0", SEEDS="1 2 3 4 5", WORK=DIR (scratch, default a temp dir).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build}
HEXEX=$BUILD/src/Tools/hexex/hexex
[[ -x $HEXEX ]] || { echo "fold-cylinders: $HEXEX not found (build the hexex target)" >&2; exit 2; }
THREADS=${THREADS:-2}
AMPS=${A:-1.5 2.0}
SEEDS=${SEEDS:-1 2 3 4 5}
OWN_WORK=0
if [[ -z ${WORK:-} ]]; then WORK=$(mktemp -d "${TMPDIR:-/tmp}/fold-cylinders.XXXXXX"); OWN_WORK=1; fi
mkdir -p "$WORK"
[[ $OWN_WORK == 1 ]] && trap 'rm -rf "$WORK"' EXIT
declare -A expected=([3]=81 [5]=135 [6]=162)
ok=0 all=0
printf '%-7s %-4s %-4s %6s %7s %12s %9s %7s %12s %7s  %s\n' valence a seed hexes non_hex report_valid validate broken remaining_anti flipped verdict
for v in 3 5 6; do
    "$HEXEX" generate cylinder --valence "$v" --radius 3 --height 3 --quiet -o "$WORK/c$v.hexex"
    for a in $AMPS; do
        for s in $SEEDS; do
            "$HEXEX" perturb "$WORK/c$v.hexex" -a "$a" --seed "$s" --quiet -o "$WORK/p.hexex"
            "$HEXEX" extract "$WORK/p.hexex" -o "$WORK/p.ovm" --report "$WORK/p.json" --threads "$THREADS" --quiet > /dev/null 2>&1 || true
            if "$HEXEX" validate "$WORK/p.ovm" > /dev/null 2>&1; then val=valid; else val=invalid; fi
            line=$(python3 - "$WORK/p.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
o, d, i = r["output"], r["darts"], r["input"]
print(o["hexes"], o["non_hex_cells"], r["valid_all_hex"], d.get("broken_cells_after_annihilation", 0),
      d["remaining_anti"], i["flipped_tets"])
PY
)
            read -r hexes nonhex rvalid broken remaining flipped <<< "$line"
            verdict=FAIL
            if [[ $hexes == "${expected[$v]}" && $nonhex == 0 && $rvalid == True && $val == valid ]]; then verdict=OK; ok=$((ok + 1)); fi
            all=$((all + 1))
            printf '%-7s %-4s %-4s %6s %7s %12s %9s %7s %12s %7s  %s\n' "$v" "$a" "$s" "$hexes" "$nonhex" "$rvalid" "$val" "$broken" "$remaining" "$flipped" "$verdict"
        done
    done
done
echo "$ok of $all cases valid all-hex with the exact hex count"
