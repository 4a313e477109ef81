#!/usr/bin/env bash
# Issue #7's curved-boundary case: the cylinder of 24 flat facets (bench/cylinder_mesh.py) refined
# 10x (HN = 0.03) or 100x (HN = 0.003, the issue's case) in its normal direction, remeshed by
# `riemesh adapt -v 1` with the given extra options (e.g. --passes 4, --approach 0). Prints the last
# pass line, the side vertices' count and largest distance to the radius, user CPU time and peak RSS.
#   bench/cylinder3d.sh [HN] [RIEMESH ADAPT OPTIONS ...]     (default HN 0.003)
# Needs build/riemesh (scripts/build.sh; RIEMESH=path: another binary), /usr/bin/python3 and time.
set -euo pipefail
cd "$(dirname "$0")/.."
R=${RIEMESH:-$PWD/build/riemesh}
hn=${1:-0.003}
shift || true
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 bench/cylinder_mesh.py "$tmp/cyl.mesh" "$tmp/cyl.sol" "$hn"
/usr/bin/time -f "%U %M" -o "$tmp/time" "$R" adapt "$tmp/cyl.mesh" --metric "$tmp/cyl.sol" \
  -o "$tmp/out.mesh" -v 1 "$@" 2>"$tmp/log" || { cat "$tmp/log"; exit 1; }
grep "^pass" "$tmp/log" | tail -1
read -r n err < <(/usr/bin/python3 bench/cylinder_mesh.py --side "$tmp/out.mesh")
read -r cpu kb <"$tmp/time"
echo "side vertices: $n, largest |r - 1|: $err; $cpu s user CPU, peak RSS $((kb / 1024)) MB"
