#!/usr/bin/env bash
# Heavy tangles for the untangler (issue 32): hex meshes perturbed with `hexex perturb -a A`
# (interior vertices moved, boundary bit for bit) until 95-96.5 % of their hexes are
# inverted, then `hexex untangle --threads T` (fixed boundary, and with the boundary on its
# own surface). Prints one table row per run:
#   case, hexes, % inverted, invalid before -> after, untangle wall s (the report's time),
#   command wall s, command CPU s (user + sys of the whole command, reading and writing included)
# and the load average before and after, so that a run on a shared machine can be judged.
#
# usage: bash scripts/untangle-heavy.sh [HEXEX_BINARY]
#   env: THREADS (default 2), AMPLITUDE (default 1.5), SEED (default 1), WORK (scratch
#        directory, default a new mktemp dir), DATA (default ../shared/data next to the repo),
#        MODES ("fixed surface" by default; "fixed" alone halves the time)
# The two published meshes are read from $DATA/hexmeshes/*.vtk.xz (skipped with a note if
# absent or if xz is missing); cubes and the cylinder are generated.
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HEXEX="${1:-$REPO_ROOT/build/src/Tools/hexex/hexex}"
THREADS="${THREADS:-2}"
AMPLITUDE="${AMPLITUDE:-1.5}"
SEED="${SEED:-1}"
DATA="${DATA:-$REPO_ROOT/../shared/data}"
MODES="${MODES:-fixed surface}"
WORK="${WORK:-$(mktemp -d /tmp/untangle-heavy.XXXXXX)}"
mkdir -p "$WORK"

if [[ ! -x "$HEXEX" ]]; then
    echo "untangle-heavy.sh: hexex binary '$HEXEX' not found or not executable" >&2
    exit 2
fi
TIME=/usr/bin/time
if [[ ! -x "$TIME" ]]; then
    echo "untangle-heavy.sh: $TIME not found (Debian: apt-get install time)" >&2
    exit 2
fi

# Inputs: NAME -> untangled hex mesh file in $WORK.
declare -a NAMES=()
add_generated() {  # name, generate arguments...
    local name=$1
    shift
    "$HEXEX" generate "$@" --quiet -o "$WORK/$name.hexex"
    "$HEXEX" extract "$WORK/$name.hexex" -o "$WORK/$name.vtu" --threads "$THREADS" --quiet
    NAMES+=("$name")
}
add_shared() {  # name (file $DATA/hexmeshes/name.vtk.xz)
    local src="$DATA/hexmeshes/$1.vtk.xz"
    if [[ ! -f "$src" ]] || ! command -v xz >/dev/null; then
        echo "note: $src not found (or no xz); skipping $1" >&2
        return
    fi
    xz -dc "$src" > "$WORK/$1.vtk"
    NAMES+=("$1")
}
add_generated cube10 cube --n 3 --scale 10
add_shared cfpc16_hollow8
add_shared sss19_pig_in
add_generated cylinder29400 cylinder --valence 5 --radius 14 --height 30 --n 6 --m 6
add_generated cube31 cube --n 5 --scale 31
add_generated cube34 cube --n 5 --scale 34

input_of() { [[ -f "$WORK/$1.vtu" ]] && echo "$WORK/$1.vtu" || echo "$WORK/$1.vtk"; }

echo "hexex: $HEXEX; threads $THREADS; perturb -a $AMPLITUDE --seed $SEED; $(nproc) cores"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '| %-26s | %7s | %10s | %-21s | %12s | %12s | %11s |\n' \
    case hexes "% inverted" "invalid before->after" "untangle s" "command s" "CPU s"
printf '|%s|%s|%s|%s|%s|%s|%s|\n' "----------------------------" "---------" "------------" \
    "-----------------------" "--------------" "--------------" "-------------"
for name in "${NAMES[@]}"; do
    tangled="$WORK/$name-tangled.vtu"
    "$HEXEX" perturb "$(input_of "$name")" -a "$AMPLITUDE" --seed "$SEED" --quiet -o "$tangled"
    for mode in $MODES; do
        args=()
        [[ $mode == fixed ]] && args+=(--fixed-boundary)
        set +e
        out=$({ "$TIME" -f "CPU %U %S WALL %e" "$HEXEX" untangle "$tangled" -o "$WORK/$name-$mode.vtu" \
                  --threads "$THREADS" "${args[@]}"; } 2>&1)
        set -e
        hexes=$(grep -o 'inverted hexes [0-9]* -> [0-9]* of [0-9]*' <<<"$out" | awk '{print $7}')
        inverted=$(grep -o 'inverted hexes [0-9]* ->' <<<"$out" | awk '{print $3}')
        invalid=$(grep -o 'invalid hexes [0-9]* -> [0-9]*' <<<"$out" | awk '{print $3 " -> " $5}')
        secs=$(grep -o 'time [0-9.e+-]* s' <<<"$out" | head -1 | awk '{print $2}')
        cpu=$(grep '^CPU' <<<"$out" | awk '{printf "%.2f", $2 + $3}')
        wall=$(grep '^CPU' <<<"$out" | awk '{print $5}')
        pct=$(awk -v a="${inverted:-0}" -v b="${hexes:-1}" 'BEGIN{printf "%.1f", 100 * a / b}')
        printf '| %-26s | %7s | %10s | %-21s | %12s | %12s | %11s |\n' \
            "$name ($mode)" "${hexes:-?}" "$pct" "${invalid:-?}" "${secs:-?}" "${wall:-?}" "${cpu:-?}"
    done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "work directory: $WORK"
