#!/usr/bin/env bash
# Issue #7's multi-region cases with curved interfaces (the README's tables "Curved interfaces with
# rims on other surfaces" and "Splits on coarse facets"): gmsh meshes of bench/geo3d/*.geo (size
# 0.2) and tests/data/cylinder_through_box.mesh, adapted by `riemesh adapt` to --hsiz or to a
# metric of bench/curved_interfaces3d_metrics.py. For each case and binary: metric lengths, the
# fraction in [1/√2, √2] and q min of the output (riemesh stats --metric on --out-metric), whether
# a note was printed, and the median user CPU of RUNS runs (binaries alternated).
#   bench/curved_interfaces3d.sh [RUNS] [OLD_RIEMESH]     (default 3 runs, the new binary only)
# Needs gmsh, /usr/bin/python3 and GNU time (scripts/setup.sh installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
NEW=$PWD/build/riemesh
runs=${1:-3}
bins=("$NEW")
[ $# -ge 2 ] && bins=("$2" "$NEW")
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
for g in cylbox cylinc cylcut sphbox sph35box; do
  gmsh -3 "bench/geo3d/$g.geo" -format mesh -o "$W/$g.mesh" >/dev/null
done
cp tests/data/cylinder_through_box.mesh "$W/ctb.mesh"
M=bench/curved_interfaces3d_metrics.py
/usr/bin/python3 $M "$W/cylbox.mesh" "$W/cyl_layer.sol" cyl 0.4 0.02 0.15 0.05
/usr/bin/python3 $M "$W/sphbox.mesh" "$W/sph_rot.sol" rot 0.3 0.3 0.02 1 2 3
/usr/bin/python3 $M "$W/sphbox.mesh" "$W/sph_shell.sol" shell 0.5 0.04 0.2 0.1
cases=(
  "cylinder through a box, --hsiz 0.1|cylbox.mesh --hsiz 0.1"
  "the same, radial size 0.02 at the side|cylbox.mesh --metric $W/cyl_layer.sol"
  "cylinder inclusion, --hsiz 0.1|cylinc.mesh --hsiz 0.1"
  "stacked cylinders, --hsiz 0.1|cylcut.mesh --hsiz 0.1"
  "cylinder_through_box (size 0.35), --hsiz 0.15|ctb.mesh --hsiz 0.15"
  "sphere in a box, 1:15 metric across (1,2,3)|sphbox.mesh --metric $W/sph_rot.sol"
  "sphere in a box, 0.04 within 0.1 of it|sphbox.mesh --metric $W/sph_shell.sol"
  "sphere r 0.35, --hsiz 0.1 --hausd 0.001|sph35box.mesh --hsiz 0.1 --hausd 0.001"
)
for c in "${cases[@]}"; do
  name=${c%%|*}
  read -r -a args <<<"${c#*|}"
  args[0]=$W/${args[0]}
  for ((b = 0; b < ${#bins[@]}; b++)); do : >"$W/cpu$b"; done
  for ((k = 0; k < runs; k++)); do
    for ((b = 0; b < ${#bins[@]}; b++)); do
      /usr/bin/time -f %U -a -o "$W/cpu$b" "${bins[$b]}" adapt "${args[@]}" -o "$W/out$b.mesh" \
        --out-metric "$W/out$b.sol" 2>"$W/log$b" >/dev/null
    done
  done
  for ((b = 0; b < ${#bins[@]}; b++)); do
    label=new; [ ${#bins[@]} -eq 2 ] && [ $b -eq 0 ] && label=old
    fig=$("$NEW" stats "$W/out$b.mesh" --metric "$W/out$b.sol" --json | /usr/bin/python3 -c "
import json, sys
m = json.load(sys.stdin)['metric']
l = m['edge_length']
print('lengths %.2f-%.2f, %.1f%% in band, q min %.3f' % (l['min'], l['max'], 100 * l['unit_fraction'], m['quality']['min']))")
    cpu=$(sort -n "$W/cpu$b" | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}')
    note=$(grep -q "note: .*interfaces" "$W/log$b" && echo ", note" || true)
    printf '%-46s %s: %s, %s s CPU%s\n' "$name" "$label" "$fig" "$cpu" "$note"
  done
done
