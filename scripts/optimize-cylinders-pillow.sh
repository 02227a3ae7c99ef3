#!/bin/bash
# Worst scaled Jacobian of `hexex extract --optimize` on generated cylinders, without and
# with --pillow (one layer of hexes along the boundary first), with the CPU time (user + sys)
# of each extract command. Usage: bash scripts/optimize-cylinders-pillow.sh
# (HEXEX=path/to/hexex, DIR=work directory, THREADS=2 by default).
H=${HEXEX:-$(cd "$(dirname "$0")/.." && pwd)/build/src/Tools/hexex/hexex}
D=${DIR:-/tmp/hexex-optimize-cylinders-pillow}; T=${THREADS:-2}; mkdir -p $D; cd $D
printf "%-3s %-4s %-8s %-8s %-10s %-10s %-9s %-9s %-8s %-8s\n" V a hexes pillowed SJ_plain SJ_pillow invalid cpu_plain cpu_pill cpu_extr
for V in 3 4 5 6; do
  $H generate cylinder --valence $V --radius 4 --height 4 --quiet -o c$V.hexex
  for A in 0 0.5 0.8; do
    if [ $A = 0 ]; then cp c$V.hexex m.hexex; else $H perturb c$V.hexex -a $A --seed 1 --quiet -o m.hexex; fi
    cpu() { /usr/bin/time -f "%U %S" -o t.txt "$@" >/dev/null 2>&1; awk '{printf "%.3f", $1 + $2}' t.txt; }
    c0=$(cpu $H extract m.hexex -o e.vtu --threads $T -q)
    c1=$(cpu $H extract m.hexex -o a.vtu --optimize --threads $T --report ra.json -q)
    c2=$(cpu $H extract m.hexex -o b.vtu --pillow --threads $T --report rb.json -q)
    python3 - "$V" "$A" "$c1" "$c2" "$c0" <<'PY'
import json, sys
a = json.load(open("ra.json"))["optimize"]; b = json.load(open("rb.json"))["optimize"]
v, amp, c1, c2, c0 = sys.argv[1:]
print(f"{v:<3} {amp:<4} {a['hexes']:<8} {b['hexes']:<8} {a['min_scaled_jacobian_after']:<10.4f} "
      f"{b['min_scaled_jacobian_after']:<10.4f} {b['invalid_after']:<9} {c1:<9} {c2:<8} {c0:<8}")
PY
  done
done
