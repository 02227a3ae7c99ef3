#!/usr/bin/env bash
# Hashes of every hex mesh writer's output (.ovm, .ovmb, .vtk, .mesh) and of the JSON report
# without timings on a fixed list of maps, for checking that a change keeps the output bytes.
# Run it with the build before and after a change and diff the two outputs.
#
# Usage: scripts/writer-hashes.sh BUILD_DIR THREADS > hashes.txt
# Environment: MAPS=DIR (generated maps, kept between runs; default a temp dir), GEN=HEXEX
# (the hexex that generates the maps, default BUILD_DIR's; give both runs the same MAPS and GEN
# so that they hash the same maps), HEXEX_SHARED=DIR (default <repo>/../shared; its cases are skipped without it).
# The list: the bundled sphere; generated cubes, cylinders (valence 3-6), rings and twisted rings
# with and without chart noise; perturbed cubes, cylinders, spheres and twisted rings; S1, S1
# perturbed, S1 x2; the pig map at scale 1 and 2; from-hex pig and cfpc16 maps at a = 0.3-0.8;
# four of them with --no-merge (polyhedra in the output).
set -uo pipefail
[[ $# -eq 2 ]] || { echo "usage: $0 BUILD_DIR THREADS" >&2; exit 2; }
BUILD=$1; THREADS=$2
ROOT=$(cd "$(dirname "$0")/.." && pwd)
HEXEX=$BUILD/src/Tools/hexex/hexex
[[ -x $HEXEX ]] || { echo "writer-hashes: $HEXEX not found" >&2; exit 2; }
GEN=${GEN:-$HEXEX}
OWN_MAPS=0
if [[ -z ${MAPS:-} ]]; then MAPS=$(mktemp -d "${TMPDIR:-/tmp}/writer-hashes-maps.XXXXXX"); OWN_MAPS=1; fi
W=$MAPS
mkdir -p "$W"
SHARED=${HEXEX_SHARED:-$ROOT/../shared}
O=$(mktemp -d "${TMPDIR:-/tmp}/writer-hashes.XXXXXX")
trap 'rm -rf "$O"; [[ $OWN_MAPS == 1 ]] && rm -rf "$W"' EXIT
gen() { local name=$1; shift; [[ -f $W/$name.hexex ]] || "$GEN" "$@" --quiet -o "$W/$name.hexex"; }
shared_xz() { [[ -f $W/$2 ]] || xz -dc "$SHARED/data/$1" > "$W/$2"; }
cases=(); add() { cases+=("$1"); }
cp "$ROOT/Examples/data/sphere.hexex" "$W/sphere.hexex"; add sphere
gen cube generate cube; add cube
gen cube_noise generate cube --n 4 --scale 5 --chart-noise 3; add cube_noise
gen cyl3 generate cylinder --valence 3; add cyl3
gen cyl5_noise generate cylinder --valence 5 --chart-noise 2; add cyl5_noise
gen cyl6 generate cylinder --valence 6 --radius 3; add cyl6
gen cyl4 generate cylinder --valence 4 --radius 5 --height 3; add cyl4
gen ring generate ring; add ring
gen ring_noise generate ring --chart-noise 4; add ring_noise
gen twisted generate twisted-ring; add twisted
gen twisted_noise generate twisted-ring --chart-noise 5; add twisted_noise
gen cube6 generate cube --n 6 --scale 6; gen cube6_p10 perturb "$W/cube6.hexex" -a 1.0 --seed 3; add cube6_p10
gen cyl3_p07 perturb "$W/cyl3.hexex" -a 0.7 --seed 1; add cyl3_p07
gen cyl5b generate cylinder --valence 5 --radius 3 --height 3; gen cyl5_p15 perturb "$W/cyl5b.hexex" -a 1.5 --seed 2; add cyl5_p15
gen cyl3b generate cylinder --valence 3 --radius 3 --height 3; gen cyl3_p20 perturb "$W/cyl3b.hexex" -a 2.0 --seed 1; add cyl3_p20
gen sphere_p05 perturb "$W/sphere.hexex" -a 0.5 --seed 1; add sphere_p05
gen twisted_p07 perturb "$W/twisted.hexex" -a 0.7 --seed 1; add twisted_p07
if [[ -d $SHARED/data ]]; then
    shared_xz S1_polycube_scale1.hexex.xz s1.hexex; add s1
    gen s1_p07 perturb "$W/s1.hexex" -a 0.7 --seed 1; add s1_p07
    shared_xz S1_polycube_scale2.hexex.xz s1x2.hexex; add s1x2
    shared_xz hexmeshes/sss19_pig_in.vtk.xz pig.vtk
    shared_xz hexmeshes/cfpc16_hollow8.vtk.xz cfpc16.vtk
    gen pig_x1 generate from-hex "$W/pig.vtk"; add pig_x1
    for c in "pig 0.3 1" "pig 0.5 1" "pig 0.6 1" "pig 0.7 4" "pig 0.8 2" "pig 0.8 12" \
             "cfpc16 0.3 1" "cfpc16 0.5 1" "cfpc16 0.6 1" "cfpc16 0.6 3" "cfpc16 0.7 3" "cfpc16 0.8 1"; do
        set -- $c
        gen "$1_$2_s$3" generate from-hex "$W/$1.vtk" --perturb "$2" --seed "$3"; add "$1_$2_s$3"
    done
    gen pig2 generate from-hex "$W/pig.vtk" --scale 2; add pig2
else
    echo "# $SHARED/data not found: shared-data cases skipped" >&2
fi
add "cube6_p10|--no-merge"; add "cyl3_p20|--no-merge"
[[ -d $SHARED/data ]] && { add "s1_p07|--no-merge"; add "pig_0.8_s2|--no-merge"; }
for cc in "${cases[@]}"; do
    c=${cc%%|*}; extra=""; [[ $cc == *"|"* ]] && extra=${cc#*|}
    line="$cc"
    for f in ovm ovmb vtk mesh; do
        "$HEXEX" extract "$W/$c.hexex" -o "$O/$c.$f" --report "$O/$c.$f.json" --threads "$THREADS" $extra > "$O/$c.log" 2>&1; rc=$?
        h=$(sha256sum < "$O/$c.$f" | cut -c1-12)
        line="$line $f=$h"
        rm -f "$O/$c.$f"
    done
    r=$(python3 -c '
import hashlib,json,sys
rep=json.load(open(sys.argv[1])); rep.pop("timings_s",None); rep.pop("threads",None)
o=rep.get("output",{})
print(hashlib.sha256(json.dumps(rep,sort_keys=True).encode()).hexdigest()[:12], o.get("hexes"), o.get("non_hex_cells"), rep.get("valid_all_hex"))' "$O/$c.ovm.json")
    echo "$line rc=$rc report=$r"
done
