#!/usr/bin/env bash
# Issue #7's real volumes: ../shared/data/vol/{bunny_vol,screw_vol} adapted to an isotropic size
# field and to an anisotropic spherical-shock layer (bench/real3d_metrics.py), in RUNS runs, the
# metric re-evaluated analytically on each new mesh, --hausd = D/1000 (D the input's bounding-box
# diagonal). Prints, for the last run: tets; edges in [1/√2, √2], length range and metric quality
# (riemesh stats --metric) against the analytic field and against the metric the remesher
# followed (--out-metric: the field intersected with the surface's curvature sizes for --hausd);
# the two-sided Hausdorff distance of the boundary to that of the run's input and to the original
# (riemesh distance; each run keeps its own input within --hausd, so the original drifts over
# runs); whether the boundary and tet refs are those of the input; CPU time and peak memory of the
# last run. GEOMETRY=1: every run with --geometry ORIGINAL (no drift from the original).
set -euo pipefail
cd "$(dirname "$0")/.."
R=${RIEMESH:-$PWD/build/riemesh}  # RIEMESH=path: another binary
runs=${1:-3}
out=${2:-/tmp/riemesh-real3d}
mkdir -p "$out"
for name in bunny_vol screw_vol; do
  orig=../shared/data/vol/$name.mesh
  hausd=$(/usr/bin/python3 -c "
import sys; sys.path.insert(0, '../shared/bench'); import medit, numpy as np
P = medit.read_mesh('$orig')['vertices']; print('%.3g' % (np.linalg.norm(P.max(0) - P.min(0)) / 1000))")
  for field in iso shell; do
    c=${name}_$field
    cp "$orig" "$out/${c}_0.mesh"
    for ((k = 1; k <= runs; k++)); do
      /usr/bin/python3 bench/real3d_metrics.py "$field" "$out/${c}_$((k - 1)).mesh" --box "$orig" \
        -o "$out/${c}_$((k - 1)).sol"
      /usr/bin/time -f "%U %M" -o "$out/time" "$R" adapt "$out/${c}_$((k - 1)).mesh" \
        --metric "$out/${c}_$((k - 1)).sol" -o "$out/${c}_$k.mesh" -q --hausd "$hausd" \
        --out-metric "$out/${c}_$k.used.sol" ${GEOMETRY:+--geometry "$orig"}
    done
    last=$out/${c}_$runs
    /usr/bin/python3 bench/real3d_metrics.py "$field" "$last.mesh" --box "$orig" -o "$last.sol"
    "$R" check "$last.mesh" > /dev/null
    "$R" stats "$last.mesh" --metric "$last.sol" --json > "$out/stats.json"
    "$R" stats "$last.mesh" --metric "$last.used.sol" --json > "$out/used.json"
    "$R" distance "$out/${c}_$((runs - 1)).mesh" "$last.mesh" --json > "$out/dist_run.json"
    "$R" distance "$orig" "$last.mesh" --json > "$out/dist.json"
    /usr/bin/python3 - "$c" "$hausd" "$orig" "$last.mesh" "$out" <<'PY'
import json, os, sys
sys.path.insert(0, os.path.join("..", "shared", "bench"))
import medit
c, hausd, orig, last, out = sys.argv[1:]
a, b = medit.read_mesh(orig), medit.read_mesh(last)
refs = lambda m, k: sorted(set(m[k + "_refs"].tolist()))
kept = all(refs(a, k) == refs(b, k) for k in ("triangles", "tetrahedra"))
j = lambda name: json.load(open(os.path.join(out, name)))
s, u = j("stats.json")["metric"], j("used.json")["metric"]
user, rss = open(os.path.join(out, "time")).read().split()
f = lambda m: "%.1f%% %.2f-%.2f q %.3f/%.3f" % (
    100 * m["edge_length"]["unit_fraction"], m["edge_length"]["min"], m["edge_length"]["max"],
    m["quality"]["min"], m["quality"]["mean"])
print("%-16s %7d tets | field: %s | used: %s | Hausdorff run %.4f orig %.4f (hausd %s) | refs %s "
      "| last run %s s CPU %.0f MB" % (
          c, j("stats.json")["counts"]["tetrahedra"], f(s), f(u), j("dist_run.json")["hausdorff"],
          j("dist.json")["hausdorff"], hausd, "kept" if kept else "CHANGED", user, int(rss) / 1024))
PY
  done
done
