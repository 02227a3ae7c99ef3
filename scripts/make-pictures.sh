#!/usr/bin/env bash
# Renders the pictures of Documentation/images from real outputs of the hexex tool.
#
# usage: bash scripts/make-pictures.sh [HEXEX_BINARY]
#
#   HEXEX_BINARY  the hexex tool (default: build/src/Tools/hexex/hexex); this script builds
#                 nothing itself, build it first (bash scripts/setup.sh, or
#                 cmake -S . -B build -G Ninja && ninja -C build hexex).
#
# Needs /usr/bin/python3 with matplotlib (Debian: apt-get install python3-matplotlib),
# override with PYTHON=... . Intermediate files go to $WORK_DIR (default: a fresh directory
# under /tmp, removed at the end unless KEEP=1).
#
# Pictures (boundary quads of the extracted hex mesh, rendered by scripts/render_boundary.py):
#   cylinder-valence3.png  generated cylinder around a singular edge of valence 3
#   sphere.png             the bundled example Examples/data/sphere.hexex
#   perturbed-cube.png     6x6x6 cube whose map was perturbed until many tets flipped
#   s1-polycube.png        the real input ../shared/data/S1_polycube_scale1.hexex.xz, if present
#   arcs-perturbed-cylinder.png  edge arcs (hexex extract --edge-arcs) of a perturbed cylinder
#                          drawn over its tet mesh (scripts/render_arcs.py)
#   untangle-cylinder.png  a perturbed valence-5 cylinder before/after hexex untangle, inverted
#                          hexes highlighted (scripts/render_untangle.py)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HEXEX="${1:-$ROOT/build/src/Tools/hexex/hexex}"
PYTHON="${PYTHON:-/usr/bin/python3}"
IMAGES="$ROOT/Documentation/images"
RENDER="$ROOT/scripts/render_boundary.py"

if [[ ! -x "$HEXEX" ]]; then
    echo "make-pictures.sh: hexex binary '$HEXEX' not found or not executable;" >&2
    echo "  build it first (bash scripts/setup.sh) or pass its path as the first argument." >&2
    exit 2
fi
if ! "$PYTHON" -c 'import matplotlib' 2>/dev/null; then
    echo "make-pictures.sh: $PYTHON cannot import matplotlib (Debian: apt-get install python3-matplotlib;" >&2
    echo "  or set PYTHON to an interpreter that has it)." >&2
    exit 1
fi

WORK="${WORK_DIR:-$(mktemp -d /tmp/hexex-pictures.XXXXXX)}"
mkdir -p "$WORK" "$IMAGES"
if [[ -z "${WORK_DIR:-}" && "${KEEP:-0}" != 1 ]]; then
    trap 'rm -rf "$WORK"' EXIT
fi
echo "hexex:   $HEXEX"
echo "work:    $WORK"

# Extracts IN.hexex to NAME.vtu (exit 3 = written but not all-hex is reported, not fatal)
# and renders Documentation/images/NAME.png.
extract_and_render() {
    local in="$1" name="$2" title="$3" view="$4"
    local rc=0
    "$HEXEX" extract "$in" -o "$WORK/$name.vtu" --report "$WORK/$name.json" || rc=$?
    if [[ $rc -ne 0 && $rc -ne 3 ]]; then
        echo "make-pictures.sh: hexex extract failed on $in (exit $rc)" >&2
        exit 1
    fi
    [[ $rc -eq 3 ]] && echo "make-pictures.sh: note: $name is not a valid all-hex mesh (exit 3)" >&2
    "$PYTHON" "$RENDER" "$WORK/$name.vtu" "$IMAGES/$name.png" --title "$title" --view "$view"
}

# 1. Cylinder around a singular edge of valence 3 (3 wedges of 4x4x4 hexes).
"$HEXEX" generate cylinder --valence 3 --radius 4 --height 4 -o "$WORK/cylinder3.hexex"
extract_and_render "$WORK/cylinder3.hexex" cylinder-valence3 \
    "generated cylinder: 3 wedges around a singular edge of valence 3" "35,-60"

# 2. The bundled example.
extract_and_render "$ROOT/Examples/data/sphere.hexex" sphere \
    "Examples/data/sphere.hexex" "22,-50"

# 3. Perturbed cube: many flipped tets, same topology as the 4x4x4 grid.
"$HEXEX" generate cube --n 6 --scale 4 -o "$WORK/cube.hexex"
"$HEXEX" perturb "$WORK/cube.hexex" -a 1.0 --seed 3 -o "$WORK/perturbed.hexex"
flipped="$("$HEXEX" info "$WORK/perturbed.hexex" --json | sed -n 's/.*"flipped_tets": *\([0-9]*\).*/\1/p')"
tets="$("$HEXEX" info "$WORK/perturbed.hexex" --json | sed -n 's/.*"tets": *\([0-9]*\).*/\1/p')"
extract_and_render "$WORK/perturbed.hexex" perturbed-cube \
    "4x4x4 cube, map perturbed until $flipped of $tets tets flipped" "25,-55"

# 4. The real S1 part, if the shared data set is there.
S1="$ROOT/../shared/data/S1_polycube_scale1.hexex.xz"
if [[ -f "$S1" ]]; then
    xz -dc "$S1" > "$WORK/s1.hexex"
    extract_and_render "$WORK/s1.hexex" s1-polycube \
        "S1_polycube_scale1 (real solver output)" "30,-60"
    rm -f "$WORK/s1.hexex"
else
    echo "make-pictures.sh: $S1 not found, skipping s1-polycube.png"
fi

# 5. Edge arcs of a perturbed cylinder (some tets flipped) over its tet mesh.
"$HEXEX" generate cylinder --valence 3 --radius 2 --height 2 --n 2 --m 1 -o "$WORK/arcs-cylinder.hexex"
"$HEXEX" perturb "$WORK/arcs-cylinder.hexex" -a 0.9 --seed 3 -o "$WORK/arcs-perturbed.hexex"
flipped="$("$HEXEX" info "$WORK/arcs-perturbed.hexex" --json | sed -n 's/.*"flipped_tets": *\([0-9]*\).*/\1/p')"
tets="$("$HEXEX" info "$WORK/arcs-perturbed.hexex" --json | sed -n 's/.*"tets": *\([0-9]*\).*/\1/p')"
"$HEXEX" extract "$WORK/arcs-perturbed.hexex" -o "$WORK/arcs-perturbed.vtu" --edge-arcs "$WORK/arcs.vtu"
"$PYTHON" "$ROOT/scripts/render_arcs.py" "$WORK/arcs-perturbed.hexex" "$WORK/arcs.vtu" \
    "$IMAGES/arcs-perturbed-cylinder.png" --view 35,-50 \
    --title "edge arcs of a valence-3 cylinder, map perturbed until $flipped of $tets tets flipped"

# 6. Untangling: a perturbed cylinder whose extraction has inverted hexes, before and after.
"$HEXEX" generate cylinder --valence 5 --radius 4 --height 3 --n 4 --m 3 -o "$WORK/untangle-cylinder.hexex"
"$HEXEX" perturb "$WORK/untangle-cylinder.hexex" -a 0.8 --seed 3 -o "$WORK/untangle-perturbed.hexex"
"$HEXEX" extract "$WORK/untangle-perturbed.hexex" -o "$WORK/untangle-before.vtu" --encoding ascii
"$HEXEX" untangle "$WORK/untangle-before.vtu" --surface-from "$WORK/untangle-perturbed.hexex" \
    -o "$WORK/untangle-after.vtu" --encoding ascii
"$PYTHON" "$ROOT/scripts/render_untangle.py" "$WORK/untangle-before.vtu" "$WORK/untangle-after.vtu" \
    "$IMAGES/untangle-cylinder.png" \
    --title "Perturbed cylinder (valence 5, hexex perturb -a 0.8): hexex extract --untangle"

ls -l "$IMAGES"/*.png
