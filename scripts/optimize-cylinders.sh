#!/bin/bash
# Worst scaled Jacobian before/after `hexex extract --optimize` on generated cylinders.
H=${HEXEX:-$(cd "$(dirname "$0")/.." && pwd)/build/src/Tools/hexex/hexex}
D=${DIR:-/tmp/hexex-optimize-cylinders}; mkdir -p $D; cd $D
for V in 3 4 5 6; do
  $H generate cylinder --valence $V --radius 4 --height 4 --quiet -o c$V.hexex
  for A in 0 0.5 0.8; do
    if [ $A = 0 ]; then cp c$V.hexex m.hexex; else $H perturb c$V.hexex -a $A --seed 1 --quiet -o m.hexex; fi
    $H extract m.hexex -o m.vtu --optimize --threads 2 --report r.json -q
    python3 - "$V" "$A" <<'PY'
import json, sys
r = json.load(open("r.json")); u = r.get("untangle", {}); o = r.get("optimize", {})
print(f"V={sys.argv[1]} a={sys.argv[2]} hexes={o.get('hexes')} extract_min={u.get('min_scaled_jacobian_before'):.4f} "
      f"untangled_min={o.get('min_scaled_jacobian_before'):.4f} optimized_min={o.get('min_scaled_jacobian_after'):.4f} "
      f"mean={o.get('mean_scaled_jacobian_before'):.3f}->{o.get('mean_scaled_jacobian_after'):.3f} invalid_after={o.get('invalid_after')} "
      f"surf_dist/diag={o.get('max_surface_distance')/o.get('diagonal'):.1e} opt_s={o.get('seconds'):.3f}")
PY
  done
done
