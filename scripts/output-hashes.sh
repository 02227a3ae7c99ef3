#!/usr/bin/env bash
# Output hashes of a fixed list of maps, for checking that a change of the extraction keeps
# the output of maps it should not touch byte-identical: per case the sha256 of the `.ovm`
# mesh and of the JSON report without its timings (`timings_s`), plus the report's summary
# counts. Run it with the build before and after a change and diff the two outputs.
#
# Usage: scripts/output-hashes.sh [BUILD_DIR] > hashes.txt   (default BUILD_DIR: <repo>/build)
# Environment: THREADS=2 (threads of the extraction), HEXEX_SHARED=DIR (default <repo>/../shared;
# the cases that need it are skipped when it is absent), WORK=DIR (scratch, default a temp dir).
# The list: the bundled sphere; generated cubes, cylinders (valence 3, 5, 6), rings and twisted
# rings, with and without chart noise; perturbed cubes, cylinders (up to 2 grid units),
# spheres and twisted rings; S1 x1, S1 x1 perturbed by 0.7, S1 x2; maps from the published hex
# meshes at a = 0.3 to 0.8 (cases that extract exactly).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build}
SHARED=${HEXEX_SHARED:-$ROOT/../shared}
THREADS=${THREADS:-2}
HEXEX=$BUILD/src/Tools/hexex/hexex
[[ -x $HEXEX ]] || { echo "output-hashes: $HEXEX not found (build the hexex target)" >&2; exit 2; }
OWN_WORK=0
if [[ -z ${WORK:-} ]]; then WORK=$(mktemp -d "${TMPDIR:-/tmp}/output-hashes.XXXXXX"); OWN_WORK=1; fi
mkdir -p "$WORK"
[[ $OWN_WORK == 1 ]] && trap 'rm -rf "$WORK"' EXIT

gen() { local name=$1; shift; [[ -f $WORK/$name.hexex ]] || "$HEXEX" "$@" --quiet -o "$WORK/$name.hexex"; }
shared_xz() { [[ -f $WORK/$2 ]] || xz -dc "$SHARED/data/$1" > "$WORK/$2"; }

cases=()
add() { cases+=("$1"); }

cp "$ROOT/Examples/data/sphere.hexex" "$WORK/sphere.hexex"; add sphere
gen cube generate cube; add cube
gen cube_noise generate cube --n 4 --scale 5 --chart-noise 3; add cube_noise
gen cyl3 generate cylinder --valence 3; add cyl3
gen cyl5_noise generate cylinder --valence 5 --chart-noise 2; add cyl5_noise
gen cyl6 generate cylinder --valence 6 --radius 3; add cyl6
gen ring generate ring; add ring
gen ring_noise generate ring --chart-noise 4; add ring_noise
gen twisted generate twisted-ring; add twisted
gen twisted_noise generate twisted-ring --chart-noise 5; add twisted_noise
gen cube6 generate cube --n 6 --scale 6; gen cube6_p10 perturb "$WORK/cube6.hexex" -a 1.0 --seed 3; add cube6_p10
gen cyl3_p07 perturb "$WORK/cyl3.hexex" -a 0.7 --seed 1; add cyl3_p07
gen cyl5b generate cylinder --valence 5 --radius 3 --height 3; gen cyl5_p15 perturb "$WORK/cyl5b.hexex" -a 1.5 --seed 2; add cyl5_p15
gen cyl3b generate cylinder --valence 3 --radius 3 --height 3; gen cyl3_p20 perturb "$WORK/cyl3b.hexex" -a 2.0 --seed 1; add cyl3_p20
gen sphere_p05 perturb "$WORK/sphere.hexex" -a 0.5 --seed 1; add sphere_p05
gen twisted_p07 perturb "$WORK/twisted.hexex" -a 0.7 --seed 1; add twisted_p07
if [[ -d $SHARED/data ]]; then
    shared_xz S1_polycube_scale1.hexex.xz s1.hexex; add s1
    gen s1_p07 perturb "$WORK/s1.hexex" -a 0.7 --seed 1; add s1_p07
    shared_xz S1_polycube_scale2.hexex.xz s1x2.hexex; add s1x2
    shared_xz hexmeshes/sss19_pig_in.vtk.xz pig.vtk
    shared_xz hexmeshes/cfpc16_hollow8.vtk.xz cfpc16.vtk
    for c in "pig 0.3 1" "pig 0.5 1" "pig 0.6 1" "pig 0.7 4" "pig 0.8 2" "pig 0.8 12" \
             "cfpc16 0.3 1" "cfpc16 0.5 1" "cfpc16 0.6 1" "cfpc16 0.6 3" "cfpc16 0.7 3" "cfpc16 0.8 1"; do
        set -- $c
        gen "$1_$2_s$3" generate from-hex "$WORK/$1.vtk" --perturb "$2" --seed "$3"; add "$1_$2_s$3"
    done
else
    echo "# $SHARED/data not found: shared-data cases skipped" >&2
fi

for c in "${cases[@]}"; do
    "$HEXEX" extract "$WORK/$c.hexex" -o "$WORK/$c.ovm" --report "$WORK/$c.json" --threads "$THREADS" > "$WORK/$c.log" 2>&1 || true
    python3 - "$WORK/$c.json" "$WORK/$c.ovm" "$c" <<'PY'
import hashlib, json, sys
rep = json.load(open(sys.argv[1]))
rep.pop("timings_s", None)
rep.pop("threads", None)
rj = hashlib.sha256(json.dumps(rep, sort_keys=True).encode()).hexdigest()[:16]
mh = hashlib.sha256(open(sys.argv[2], "rb").read()).hexdigest()[:16]
o = rep.get("output", {})
print(f"{sys.argv[3]:16s} ovm={mh} report={rj} hexes={o.get('hexes')} non_hex={o.get('non_hex_cells')} valid={rep.get('valid_all_hex')}")
PY
done
