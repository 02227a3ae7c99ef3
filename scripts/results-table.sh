#!/usr/bin/env bash
# Runs the hexex tool on generated cases, perturbed (defective) maps and the real data in
# ../shared/data, and prints a Markdown table of the results (Documentation/results.md).
# Usage: scripts/results-table.sh [path/to/hexex]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
hexex="${1:-$root/build/src/Tools/hexex/hexex}"
data="$root/../shared/data"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# Pull one number out of the flat-ish report JSON: key inside a given section.
field() {  # field FILE SECTION KEY
  /usr/bin/env python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); v=r[sys.argv[2]][sys.argv[3]] if sys.argv[2] else r[sys.argv[3]]; print(str(v).lower() if isinstance(v,bool) else (round(v,3) if isinstance(v,float) else v))' "$@"
}

row() {  # row NAME INPUT EXPECTED
  local name="$1" in="$2" expected="$3" rep="$tmp/r.json" st=0
  "$hexex" extract "$in" -o "$tmp/out.vtu" --report "$rep" --quiet || st=$?
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$name" \
    "$(field "$rep" input tets)" "$(field "$rep" input flipped_tets)" "$(field "$rep" input degenerate_tets)" \
    "$expected" "$(field "$rep" output hexes)" "$(field "$rep" output vertices)" \
    "$(field "$rep" output non_hex_cells)" "$(field "$rep" quality inverted_hexes)" \
    "$(field "$rep" "" valid_all_hex) (exit $st)"
}

echo '| input | tets | flipped | degenerate | expected hexes | hexes | vertices | non-hex | inverted hexes | valid all-hex |'
echo '|---|---|---|---|---|---|---|---|---|---|'
"$hexex" generate cube --n 4 --scale 6 -o "$tmp/cube.hexex" --quiet
row "cube n=4 s=6" "$tmp/cube.hexex" "216 (343 vertices)"
"$hexex" generate cube --n 4 --scale 6 --chart-noise 3 --fp-noise 1e-11 -o "$tmp/cubec.hexex" --quiet
row "cube n=4 s=6, random charts + 1e-11 noise" "$tmp/cubec.hexex" "216 (343 vertices)"
for a in 0.2 0.5 1.0 2.0; do
  "$hexex" perturb "$tmp/cube.hexex" -a "$a" --seed 1 -o "$tmp/p.hexex" --quiet
  row "cube n=4 s=6 perturbed a=$a" "$tmp/p.hexex" "216 (343 vertices)"
done
for k in 3 5 6; do
  "$hexex" generate cylinder --valence "$k" --radius 3 --height 3 --n 3 --m 3 -o "$tmp/cyl.hexex" --quiet
  row "cylinder valence $k, R=H=3" "$tmp/cyl.hexex" "$((k * 27))"
  "$hexex" perturb "$tmp/cyl.hexex" -a 0.3 --seed 1 -o "$tmp/p.hexex" --quiet
  row "cylinder valence $k perturbed a=0.3" "$tmp/p.hexex" "$((k * 27))"
done
"$hexex" generate twisted-ring --length 8 --width 2 --nu 8 --nv 2 --chart-noise 5 -o "$tmp/tr.hexex" --quiet
row "twisted ring 8x2x2, random charts" "$tmp/tr.hexex" "32"
row "sphere.hexex (bundled)" "$root/Examples/data/sphere.hexex" "216 (param. volume)"
for s in 1 2 3; do
  f="$data/S1_polycube_scale$s.hexex.xz"
  [ -f "$f" ] || continue
  xz -dc "$f" > "$tmp/s1.hexex"
  row "S1 polycube scale $s" "$tmp/s1.hexex" "$(case $s in 1) echo 10288;; 2) echo 84347;; 3) echo 283058;; esac) (param. volume)"
done
