#!/usr/bin/env bash
# Issue #4's real 2D cases: the lake of Geneva with a shore-refined metric and the NACA 0012 airfoil
# with a wake-aligned anisotropic metric (bench/real2d_metrics.py), adapted in RUNS runs, the metric
# re-evaluated on each new mesh; prints `riemesh stats --json` figures of the last run and writes
# OUT/<case>.png.   bench/real2d.sh [RUNS] [OUT]   (default 4, /tmp/riemesh-real2d)
set -euo pipefail
cd "$(dirname "$0")/.."
R=$PWD/build/riemesh
runs=${1:-4}
out=${2:-/tmp/riemesh-real2d}
mkdir -p "$out"
for c in lake:lac-leman wake:naca0012; do
  field=${c%%:*}; name=${c#*:}
  cp "../shared/data/2d/$name.mesh" "$out/${name}_0.mesh"
  for ((k = 1; k <= runs; k++)); do
    /usr/bin/python3 bench/real2d_metrics.py "$field" "$out/${name}_$((k - 1)).mesh" -o "$out/${name}_$((k - 1)).sol"
    /usr/bin/time -f "%e" -o "$out/time" "$R" adapt "$out/${name}_$((k - 1)).mesh" \
      --metric "$out/${name}_$((k - 1)).sol" -o "$out/${name}_$k.mesh" -q --hausd 0.002
  done
  /usr/bin/python3 bench/real2d_metrics.py "$field" "$out/${name}_$runs.mesh" -o "$out/${name}_$runs.sol"
  "$R" stats "$out/${name}_$runs.mesh" --metric "$out/${name}_$runs.sol" --json |
    /usr/bin/python3 -c "import json,sys; j=json.load(sys.stdin); m=j['metric']; print('%-10s %7d triangles, edges in [1/√2, √2] %.1f%%, length %.2f-%.2f, metric quality min %.3f mean %.3f, last run %s s' % ('$name', j['counts']['triangles'], 100*m['edge_length']['unit_fraction'], m['edge_length']['min'], m['edge_length']['max'], m['quality']['min'], m['quality']['mean'], open('$out/time').read().strip()))"
  "$R" check "$out/${name}_$runs.mesh" > /dev/null
  "$R" render "$out/${name}_$runs.mesh" --metric "$out/${name}_$runs.sol" -o "$out/$name.png" --width 700
done
