#!/usr/bin/env bash
# Per-stage scaling from 1 to 2 threads, and every writer against the extraction, on the
# cylinder (valence 6, 1.57M hexes) and pig x2 (one chart per hex): prints one table per case
# with, per stage, the best wall and CPU time at 1 and 2 threads (stage_benchmark) and the
# wall speed-up, then one table of the writers (writer_benchmark at 2 threads: best wall and
# its CPU; "faces" is the OpenVolumeMesh numbering that .ovm/.ovmb include) with each
# writer's wall and CPU time as a fraction of the 2-thread extraction's.
#
# Usage: scripts/stage-scaling.sh [BUILD_DIR]     (default BUILD_DIR: <repo>/build; needs the
#        targets hexex, stage_benchmark and writer_benchmark)
# Environment: REPEAT=3 (runs per measurement, the best is printed), CASES="cyl pig2",
#              HEXEX_SHARED=DIR (default <repo>/../shared; pig2 is skipped without it),
#              WRITE_TO=DIR (the writers write files into DIR, as hexex does, instead of
#              growing an std::ostringstream; the times then include the kernel's copy of
#              the bytes into the page cache).
# On a shared machine the wall columns mean little; the CPU columns stay comparable.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build}
SHARED=${HEXEX_SHARED:-$ROOT/../shared}
REPEAT=${REPEAT:-3}
CASES=${CASES:-"cyl pig2"}
HEXEX=$BUILD/src/Tools/hexex/hexex
STAGES=$BUILD/src/Benchmarks/stage_benchmark
WRITERS=$BUILD/src/Benchmarks/writer_benchmark
for x in "$HEXEX" "$STAGES" "$WRITERS"; do
    [[ -x $x ]] || { echo "stage-scaling: $x not found (build hexex stage_benchmark writer_benchmark)" >&2; exit 2; }
done
TMP=$(mktemp -d "${TMPDIR:-/tmp}/stage-scaling.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

echo "stage scaling, best of $REPEAT, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for c in $CASES; do
    case $c in
    cyl) "$HEXEX" generate cylinder --valence 6 --radius 64 --height 64 --quiet -o "$TMP/$c.hexex" ;;
    pig2)
        if [[ ! -f $SHARED/data/hexmeshes/sss19_pig_in.vtk.xz ]]; then echo "$c: no shared data, skipped"; continue; fi
        xz -dc "$SHARED/data/hexmeshes/sss19_pig_in.vtk.xz" > "$TMP/pig.vtk"
        "$HEXEX" generate from-hex "$TMP/pig.vtk" --scale 2 --quiet -o "$TMP/$c.hexex" ;;
    *) echo "stage-scaling: unknown case $c" >&2; exit 2 ;;
    esac
    "$STAGES" "$TMP/$c.hexex" 1 "$REPEAT" > "$TMP/s1.txt"
    "$STAGES" "$TMP/$c.hexex" 2 "$REPEAT" > "$TMP/s2.txt"
    "$HEXEX" extract "$TMP/$c.hexex" -o "$TMP/$c.vtu" --threads 2 --quiet || [[ $? -eq 3 ]]
    "$WRITERS" "$TMP/$c.vtu" 2 "$REPEAT" ${WRITE_TO:+all "$WRITE_TO"} > "$TMP/w.txt"
    python3 - "$c" "$TMP/s1.txt" "$TMP/s2.txt" "$TMP/w.txt" <<'EOF'
import os, sys
case, f1, f2, fw = sys.argv[1:]
def stages(path):
    rows = {}
    for line in open(path).read().splitlines()[1:]:
        name, wall, cpu = line.split()
        rows[name] = (float(wall), float(cpu))
    return rows
s1, s2 = stages(f1), stages(f2)
print(f"\n{case}: stage       1 thread wall / cpu    2 threads wall / cpu    wall speed-up")
for name in s1:
    w1, c1 = s1[name]
    w2, c2 = s2.get(name, (0.0, 0.0))
    up = f"{w1 / w2:.2f}x" if w2 > 0 else "-"
    print(f"  {name:<12} {w1:8.3f} / {c1:6.3f}      {w2:8.3f} / {c2:6.3f}        {up}")
ext, extCpu = s2["total"]
print(f"{case}: writer (2 threads{', to files' if os.environ.get('WRITE_TO') else ', to memory'})  wall / cpu     wall / extraction wall ({ext:.3f} s)   cpu / extraction cpu ({extCpu:.3f} s)")
for line in open(fw).read().splitlines()[1:]:
    parts = line.split()
    name, wall, cpu = parts[0], float(parts[1]), float(parts[4])
    print(f"  {name:<8} {wall:8.3f} / {cpu:6.3f}     {wall / ext:.2f}x                               {cpu / extCpu:.2f}x")
EOF
done
