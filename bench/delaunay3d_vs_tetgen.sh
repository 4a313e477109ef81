#!/usr/bin/env bash
# The 3D Delaunay kernel against Debian's TetGen 1.5 on the same points (bench/delaunay3d_inputs.py):
#   points:   our delaunay3d (BRIO order, median of RUNS runs, reading excluded) vs TetGen's own
#             "Delaunay seconds" (median of 3 runs of `tetgen -V -N -E -F`, no output written);
#             tetrahedron counts (equal for points in general position).
#   surfaces: the Delaunay tetrahedralisation of each closed surface's vertices (tets, time), the
#             surface triangles missing from it, and `riemesh mesh`'s boundary recovery (Steiner
#             points on edges + in faces, tets, minimum dihedral angle by bench/min_dihedral.py,
#             median CPU time of 3 runs) next to TetGen's (`tetgen -p`: Steiner points, tets,
#             minimum dihedral angle of its .ele output, its total seconds).
# Usage: bench/delaunay3d_vs_tetgen.sh [BUILD_DIR] [RUNS]   (prints a Markdown table)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
runs=${2:-5}
bench=$build/bench/riemesh_bench_delaunay3d
riemesh=$build/riemesh
command -v tetgen >/dev/null || { echo "tetgen not installed (scripts/setup.sh)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$here/delaunay3d_inputs.py" "$here/../../shared/data" "$tmp" >/dev/null

# tetgen_seconds FILE FLAGS KEY: median over 3 runs of TetGen's reported "KEY seconds".
tetgen_seconds() {
  for _ in 1 2 3; do tetgen $2 "$1" 2>&1 | awk -v k="^$3 seconds:" '$0 ~ k {print $NF}'; done |
    sort -g | sed -n 2p
}
tetgen_count() {  # FILE FLAGS KEY: a statistics line of TetGen's report
  tetgen $2 "$1" 2>&1 | awk -v k="$3" 'index($0, k) {print $NF; exit}'
}

echo "| points | n | tets (ours) | tets (TetGen) | ours (s) | TetGen Delaunay (s) | ours (M points/s) |"
echo "|---|---|---|---|---|---|---|"
for name in random_100000 random_1000000 grid_50 cluster; do
  node=$tmp/$name.node
  read -r _ n _ tets _ secs < <("$bench" --node "$node" --runs "$runs")
  ttets=$(tetgen_count "$node" "-V -N -E -F" "Mesh tetrahedra:")
  tsecs=$(tetgen_seconds "$node" "-V -N -E -F" "Delaunay")
  rate=$(awk -v n="$n" -v s="$secs" 'BEGIN {printf "%.2f", n / s / 1e6}')
  echo "| $name | $n | $tets | $ttets | $secs | $tsecs | $rate |"
done
echo
echo "| surface | vertices | triangles | Delaunay tets (ours) | Delaunay (s) | missing faces / edges | ours: Steiner (edges + faces) | ours: tets | ours: min dihedral | ours: mesh CPU (s) | TetGen -p Steiner | TetGen -p tets | TetGen -p min dihedral | TetGen -p total (s) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for mesh in "$tmp"/*.surf.mesh; do
  name=$(basename "$mesh" .surf.mesh)
  read -r _ n _ tets _ secs < <("$bench" --node "$tmp/$name.surf.node" --runs "$runs")
  tris=$(awk '/^Triangles/ {getline; print; exit}' "$mesh")
  # riemesh mesh: boundary recovery; median CPU time (user + sys) of 3 runs, file I/O included.
  if msg=$("$riemesh" mesh --nofill "$mesh" -o "$tmp/$name.vol.mesh" 2>&1); then
    missing=$(printf '%s' "$msg" | sed -n 's/.*tetrahedra, \([0-9]*\) faces and \([0-9]*\) edges missing.*/\1 \/ \2/p')
    steiner=$(printf '%s' "$msg" | sed -n 's/.*; \([0-9]*\) Steiner points (\([0-9]*\) on edges, \([0-9]*\) in faces.*/\1 (\2 + \3)/p')
    read -r dihedral vtets < <(/usr/bin/python3 "$here/min_dihedral.py" "$tmp/$name.vol.mesh")
    cpu=$(for _ in 1 2 3; do
            /usr/bin/time -f "%U %S" "$riemesh" mesh -q --nofill "$mesh" -o "$tmp/$name.vol.mesh" 2>&1 >/dev/null |
              awk '{print $1 + $2}'
          done | sort -g | sed -n 2p)
  else
    missing="-"; steiner="error: ${msg##*: }"; dihedral="-"; vtets="-"; cpu="-"
  fi
  report=$(cd "$tmp" && tetgen -pV "$mesh" 2>&1 || true)
  tsteiner=$(printf '%s\n' "$report" | awk '/Steiner points/ {s += $NF} END {print s + 0}')
  ttets=$(printf '%s\n' "$report" | awk '/Mesh tetrahedra:/ {print $NF; exit}')
  tsecs=$(printf '%s\n' "$report" | awk '/^Total running seconds:/ {print $NF; exit}')
  tdihedral=$(/usr/bin/python3 "$here/min_dihedral.py" "$tmp/$name.surf.1" 2>/dev/null | awk '{print $1}')
  echo "| $name | $n | $tris | $tets | $secs | $missing | $steiner | $vtets | $dihedral | $cpu | $tsteiner | $ttets | ${tdihedral:--} | $tsecs |"
done
