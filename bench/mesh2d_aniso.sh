#!/usr/bin/env bash
# `riemesh mesh --metric` with constant anisotropic metrics (sizes 1:10, turned by 0 or 30
# degrees) on the Lake Geneva boundary (../shared/data/2d/lac-leman.mesh, sizes 1/40 and 1/400 of
# its box) and the unit square (0.01 and 0.001 on 20 edges per side; 0.1 and 0.001 on 4 edges
# per side, each about 125 units long in the metric): passes, wall time, triangles, and by
# `riemesh stats --metric` the fraction of edges in [1/√2, √2] and the metric quality, min and
# mean (the metric is constant, so it is known at the output's vertices).
#   bench/mesh2d_aniso.sh [RIEMESH] [OUT]    (default build/riemesh, /tmp/riemesh-aniso)
set -euo pipefail
cd "$(dirname "$0")/.."
R=$(realpath "${1:-build/riemesh}")
out=${2:-/tmp/riemesh-aniso}
mkdir -p "$out"
"$R" convert --boundary ../shared/data/2d/lac-leman.mesh "$out/lac.mesh" >/dev/null
for n in 20 4; do
/usr/bin/python3 - "$out/square$n.mesh" "$n" <<'PY'
import sys
n = int(sys.argv[2])  # the unit square's boundary, n edges per side, counter-clockwise
pts = [(k / n, 0) for k in range(n)] + [(1, k / n) for k in range(n)] + \
      [(1 - k / n, 1) for k in range(n)] + [(0, 1 - k / n) for k in range(n)]
with open(sys.argv[1], "w") as f:
    f.write("MeshVersionFormatted 2\nDimension 2\nVertices\n%d\n" % len(pts))
    f.writelines("%.17g %.17g 0\n" % p for p in pts)
    f.write("Edges\n%d\n" % len(pts))
    f.writelines("%d %d 1\n" % (i + 1, (i + 1) % len(pts) + 1) for i in range(len(pts)))
    f.write("End\n")
PY
done
printf '%-8s %-4s | %-6s %-6s %-9s %-7s %-6s %-6s\n' domain deg passes time triangles in-band q-min q-mean
for c in "lac 1.5255 0.15255 0" "lac 1.5255 0.15255 30" "square20 0.01 0.001 30" \
  "square4 0.1 0.001 30"; do
  set -- $c
  /usr/bin/python3 bench/const_metric.py "$out/$1.mesh" "$out/in.sol" "$2" "$3" "$4"
  /usr/bin/time -f "%e" -o "$out/t" "$R" mesh "$out/$1.mesh" --metric "$out/in.sol" -o "$out/o.mesh" \
    --hgrad 0 >"$out/log" 2>&1
  /usr/bin/python3 bench/const_metric.py "$out/o.mesh" "$out/o.sol" "$2" "$3" "$4"
  "$R" stats --json "$out/o.mesh" --metric "$out/o.sol" >"$out/s.json"
  /usr/bin/python3 - "$out/s.json" "$1" "$4" "$(grep -c '^pass' "$out/log")" "$(cat "$out/t")" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
m = j["metric"]
print("%-8s %-4s | %-6s %-6s %-9d %-7s %-6.3f %-6.3f" % (sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5],
      j["counts"]["triangles"], "%.1f%%" % (100 * m["edge_length"]["unit_fraction"]), m["quality"]["min"], m["quality"]["mean"]))
PY
done
