#!/usr/bin/env bash
# Renders Documentation/images/quad-cone5.png: the quad mesh that `hexex quad` extracts from
# a generated disk around a cone of valence 5 whose map was perturbed (a = 0.5, many flipped
# triangles), drawn over the input triangles.
#
# usage: bash scripts/make-quad-picture.sh [HEXEX_BINARY]
# Needs python3 with matplotlib (Debian: apt-get install python3-matplotlib).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HEXEX="${1:-$ROOT/build/src/Tools/hexex/hexex}"
PYTHON="${PYTHON:-/usr/bin/python3}"
if [[ ! -x "$HEXEX" ]]; then
    echo "make-quad-picture.sh: hexex binary '$HEXEX' not found; build it first (bash scripts/setup.sh)" >&2
    exit 2
fi
WORK="$(mktemp -d /tmp/hexex-quad-picture.XXXXXX)"
trap 'rm -rf "$WORK"' EXIT
"$HEXEX" generate cone-disk --valence 5 --radius 4 --n 8 -o "$WORK/disk.obj"
"$HEXEX" perturb "$WORK/disk.obj" -a 0.5 --seed 7 -o "$WORK/perturbed.obj"
"$HEXEX" quad "$WORK/perturbed.obj" -o "$WORK/quads.off" --report "$WORK/report.json"
"$PYTHON" "$ROOT/scripts/render_quads.py" "$WORK/perturbed.obj" "$WORK/quads.off" \
    "$ROOT/Documentation/images/quad-cone5.png" \
    --title "hexex quad: valence-5 cone disk, map perturbed by a = 0.5 (80 quads, 101 vertices)"
