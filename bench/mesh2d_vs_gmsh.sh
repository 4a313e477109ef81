#!/usr/bin/env bash
# `riemesh mesh` against Gmsh (Debian's gmsh, default 2D algorithm) on the boundaries of the shared
# 2D meshes, at the same sizes: (keep) the boundary kept edge for edge, sizes from the boundary
# edges; (h) a uniform size h, the boundary remeshed. Prints triangles, Euclidean quality (min,
# mean, as `riemesh stats` measures it), the median edge length and the median wall time of RUNS
# runs, for each tool. Then the Gmsh .geo geometries of tests/data/geo, read by both tools from
# the same file (sizes from the points' lc; size "lc").
#   bench/mesh2d_vs_gmsh.sh [RUNS] [OUT]    (default 5, /tmp/riemesh-mesh2d)
set -euo pipefail
cd "$(dirname "$0")/.."
R=$PWD/build/riemesh
runs=${1:-5}
out=${2:-/tmp/riemesh-mesh2d}
mkdir -p "$out"

median_time() {  # median_time CMD...: runs CMD $runs times, prints the median wall time (s)
  for ((k = 0; k < runs; k++)); do
    /usr/bin/time -f "%e" -o "$out/t" "$@" >/dev/null 2>&1
    cat "$out/t"
  done | sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'
}
quality() {  # triangles, min and mean Euclidean quality, median edge length of a mesh
  local q e
  q=$("$R" stats --json "$1" | /usr/bin/python3 -c "import json,sys; j=json.load(sys.stdin); print('%7d %6.3f %6.3f' % (j['counts']['triangles'], j['quality']['min'], j['quality']['mean']))")
  e=$(/usr/bin/python3 -c "
import meshio, numpy as np, sys
m = meshio.read(sys.argv[1]); p = m.points[:, :2]
t = np.vstack([c.data for c in m.cells if c.type == 'triangle'])
e = np.unique(np.sort(np.vstack([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), 1), axis=0)
print('%7.3g' % np.median(np.linalg.norm(p[e[:, 0]] - p[e[:, 1]], axis=1)))" "$1" 2>/dev/null | tail -1)
  echo "$q $e"
}

printf '%-10s %-5s | %-36s | %-36s\n' case size "riemesh: tris qmin qmean edge time" "gmsh: tris qmin qmean edge time"
for name in aile lac-leman naca0012; do
  "$R" convert --boundary "../shared/data/2d/$name.mesh" "$out/$name-domain.mesh" >/dev/null
  case $name in aile) h=0.5 ;; lac-leman) h=0.5 ;; naca0012) h=0.05 ;; esac
  for mode in keep $h; do
    if [ "$mode" = keep ]; then opts=(); else opts=(--hsiz "$mode"); fi
    "$R" mesh "$out/$name-domain.mesh" -o "$out/$name-$mode-riemesh.mesh" -q "${opts[@]}" >/dev/null
    tr=$(median_time "$R" mesh "$out/$name-domain.mesh" -o "$out/$name-$mode-riemesh.mesh" -q "${opts[@]}")
    /usr/bin/python3 bench/mesh2d_geo.py "$out/$name-domain.mesh" "$out/$name-$mode.geo" "$mode"
    gmsh -2 -format msh41 "$out/$name-$mode.geo" -o "$out/$name-$mode-gmsh.msh" >/dev/null
    tg=$(median_time gmsh -2 -format msh41 "$out/$name-$mode.geo" -o "$out/$name-$mode-gmsh.msh")
    printf '%-10s %-5s | %s %5ss | %s %5ss\n' "$name" "$mode" \
      "$(quality "$out/$name-$mode-riemesh.mesh")" "$tr" "$(quality "$out/$name-$mode-gmsh.msh")" "$tg"
  done
done
for geo in tests/data/geo/*.geo; do
  name=$(basename "$geo" .geo)
  "$R" mesh "$geo" -o "$out/$name-geo-riemesh.mesh" -q >/dev/null
  tr=$(median_time "$R" mesh "$geo" -o "$out/$name-geo-riemesh.mesh" -q)
  gmsh -2 -format msh41 "$geo" -o "$out/$name-geo-gmsh.msh" >/dev/null
  tg=$(median_time gmsh -2 -format msh41 "$geo" -o "$out/$name-geo-gmsh.msh")
  printf '%-10s %-5s | %s %5ss | %s %5ss\n' "${name:0:10}" lc \
    "$(quality "$out/$name-geo-riemesh.mesh")" "$tr" "$(quality "$out/$name-geo-gmsh.msh")" "$tg"
done
