#!/usr/bin/env bash
# Side by side with HexHex: runs our `hexex` and HexHex on the same inputs in one run and
# prints per case the extraction-only time of both and the ratio, and the end-to-end time
# through the command-line tools (read + extract + write .ovmb) and the ratio.
#
# Usage: scripts/side-by-side.sh [BUILD_DIR]        (default BUILD_DIR: <repo>/build)
# Environment:
#   THREADS=2        threads for both tools
#   CASES="..."      subset of: cube20 cube40 cylinder6 s1x2 pig2 pig2p (default: all)
#   TIMEOUT=900      seconds before a HexHex run is killed
#   REPEAT=1         runs per case (ours and HexHex alternating); the best time of each is printed
#   HEXEX_SHARED=DIR the shared data (default <repo>/../shared); skipped cleanly when absent
# HexHex is built once by ../shared/anchors/hexhex/build.sh (5-8 min the first time).
#
# Measured:
#   ours extract   = sum of the extraction stages of `hexex extract --report` (preprocess,
#                    vertices, darts, connect, postprocess, assemble; not read/write/checks)
#   HexHex extract = `t_extract_s` of `hexhex_run` (HexHex::extractHexMesh, loading not timed)
#   end to end     = wall time of `hexex extract IN -o OUT.ovmb --threads N` against
#                    `HexHex -i IN -o OUT.ovmb --nthreads N`
# Where HexHex refuses an input (flipped or degenerate tets), its reason is printed.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
SHARED=${HEXEX_SHARED:-$ROOT/../shared}
BUILD=${1:-$ROOT/build}
THREADS=${THREADS:-2}
TIMEOUT=${TIMEOUT:-900}
REPEAT=${REPEAT:-1}
CASES=${CASES:-"cube20 cube40 cylinder6 s1x2 pig2 pig2p"}
HEXEX=$BUILD/src/Tools/hexex/hexex

if [[ ! -d $SHARED/anchors/hexhex || ! -d $SHARED/data ]]; then
    echo "side-by-side: $SHARED (HexHex sources and data) not found; skipping"
    exit 0
fi
if [[ ! -x $HEXEX ]]; then
    echo "side-by-side: $HEXEX not found (build the hexex target first)" >&2
    exit 2
fi
HEXHEX_RUN=$(bash "$SHARED/anchors/hexhex/build.sh" | tail -n1)
HEXHEX_CLI=$(dirname "$HEXHEX_RUN")/HexHex
[[ -x $HEXHEX_RUN && -x $HEXHEX_CLI ]] || { echo "side-by-side: HexHex build failed" >&2; exit 2; }

TMP=$(mktemp -d "${TMPDIR:-/tmp}/side-by-side.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

now() { date +%s.%N; }
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

# Builds the input of case $1 into $TMP/$1.hexex.
make_input() {
    local out=$TMP/$1.hexex
    case $1 in
    cube20) "$HEXEX" generate cube --n 40 --scale 20 --quiet -o "$out" ;;
    cube40) "$HEXEX" generate cube --n 80 --scale 40 --quiet -o "$out" ;;
    cylinder6) "$HEXEX" generate cylinder --valence 6 --radius 64 --height 64 --quiet -o "$out" ;;
    s1x2) xz -dc "$SHARED/data/S1_polycube_scale2.hexex.xz" > "$out" ;;
    pig2 | pig2p)
        [[ -f $TMP/pig.vtk ]] || xz -dc "$SHARED/data/hexmeshes/sss19_pig_in.vtk.xz" > "$TMP/pig.vtk"
        local perturb=0
        [[ $1 == pig2p ]] && perturb=0.3
        "$HEXEX" generate from-hex "$TMP/pig.vtk" --scale 2 --perturb "$perturb" --quiet -o "$out" ;;
    *) echo "side-by-side: unknown case $1" >&2; return 1 ;;
    esac
}

min() { python3 -c "import sys; v=[float(x) for x in sys.argv[1:] if x]; print(f'{min(v):.2f}' if v else '-')" "$@"; }
ratio() {
    python3 -c "import sys
try: print(f'{float(sys.argv[2]) / float(sys.argv[1]):.1f}x')
except Exception: print('-')" "$1" "$2"
}

echo "side by side with HexHex, $THREADS threads, best of $REPEAT, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores"
printf '%-10s %9s %9s | %9s %9s %7s | %9s %9s %7s\n' case tets hexes ours_ext hh_ext ratio ours_e2e hh_e2e ratio
for c in $CASES; do
    make_input "$c"
    in=$TMP/$c.hexex
    ours_ext=() ours_e2e=() hh_ext=() hh_e2e=() refused="" failed=""
    for ((r = 0; r < REPEAT; ++r)); do
        # Ours, end to end (the report gives the extraction stages of the same run).
        t0=$(now)
        set +e
        "$HEXEX" extract "$in" -o "$TMP/ours.ovmb" --threads "$THREADS" --quiet --report "$TMP/ours.json" 2> "$TMP/ours.err"
        st=$?
        set -e
        t1=$(now)
        if [[ $st -ne 0 && $st -ne 3 ]]; then
            failed="hexex failed (exit $st): $(head -c 300 "$TMP/ours.err")"
            break
        fi
        ours_e2e+=("$(python3 -c "print($t1 - $t0)")")
        ours_ext+=("$(json "$TMP/ours.json" "sum(d['timings_s'][k] for k in ('preprocess','vertices','darts','connect','postprocess','assemble'))")")
        [[ -n $refused ]] && continue
        # HexHex, extraction only.
        set +e
        timeout "$TIMEOUT" "$HEXHEX_RUN" --threads "$THREADS" "$in" > "$TMP/hh.json" 2> "$TMP/hh.err"
        hst=$?
        set -e
        if [[ $hst -eq 3 ]]; then
            refused="HexHex refused: $(grep -E 'Error:|Detected .* Tets' "$TMP/hh.err" | tail -n2 | sed 's/^HexHex: //' | tr '\n' ' ')"
            continue
        elif [[ $hst -ne 0 && $hst -ne 4 ]]; then
            refused="HexHex failed (exit $hst): $(tail -n1 "$TMP/hh.err")"
            continue
        fi
        hh_ext+=("$(json "$TMP/hh.json" "d['t_extract_s']")")
        # HexHex, end to end through its CLI.
        t0=$(now)
        set +e
        timeout "$TIMEOUT" "$HEXHEX_CLI" -i "$in" -o "$TMP/hh.ovmb" --nthreads "$THREADS" > "$TMP/hhcli.out" 2>&1
        hst=$?
        set -e
        t1=$(now)
        [[ $hst -eq 0 ]] && hh_e2e+=("$(python3 -c "print($t1 - $t0)")")
        rm -f "$TMP/ours.ovmb" "$TMP/hh.ovmb"
    done
    if [[ -n $failed ]]; then
        echo "$c: $failed"
        continue
    fi
    tets=$(json "$TMP/ours.json" "d['input']['tets']")
    hexes=$(json "$TMP/ours.json" "d['output']['hexes']")
    oe=$(min "${ours_ext[@]}") oa=$(min "${ours_e2e[@]}") he=$(min "${hh_ext[@]}") ha=$(min "${hh_e2e[@]}")
    [[ -n $refused ]] && he=refused ha=refused
    printf '%-10s %9s %9s | %9s %9s %7s | %9s %9s %7s   %s\n' "$c" "$tets" "$hexes" "$oe" "$he" "$(ratio "$oe" "$he")" \
        "$oa" "$ha" "$(ratio "$oa" "$ha")" "$refused"
    rm -f "$in"
done
echo "times in seconds (best of $REPEAT, ours and HexHex alternating); ratio = HexHex time / our time (above 1: ours is faster)"
