#!/usr/bin/env bash
# Checks that two riemesh binaries make byte-identical 2D adaptations: the 7 cases of
# bench/adapt2d_cases.sh run pass by pass with NEW (metric re-evaluated by ../shared/bench on
# each new mesh) and OLD on the same inputs, then uniform --hsiz refinements of the 20 x 20
# square and one run with the default --hgrad. Prints one line per comparison (same / DIFF).
#   bench/adapt2d_identical.sh OLD NEW [PASSES]      (default: 5 passes)
# Needs Debian's python3-numpy.
set -uo pipefail
cd "$(dirname "$0")/.."
H=$(cd ../shared/bench && pwd)
OLD=$1 NEW=$2 P=${3:-5}
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
same() { if cmp -s "$1" "$2"; then echo same; else echo DIFF; fi; }
for c in linear2d polar2d polar2d-2 polar2d-mild "linear2d:h0=0.00001" "linear2d:s=0.1" \
         "polar2d:s=0.1"; do
  d="$W/${c//[:=]/_}"
  mkdir -p "$d"
  /usr/bin/python3 "$H/cases.py" init "$c" -o "$d/p0" >/dev/null
  m="$d/p0.mesh" s="$d/p0.sol"
  for k in $(seq 1 "$P"); do
    if [ "$k" -gt 1 ]; then
      /usr/bin/python3 "$H/cases.py" metric "$c" "$m" -o "$d/m$k.sol" >/dev/null
      s="$d/m$k.sol"
    fi
    "$NEW" adapt "$m" --metric "$s" -o "$d/new$k.mesh" -q --hgrad 0
    "$OLD" adapt "$m" --metric "$s" -o "$d/old$k.mesh" -q --hgrad 0
    echo "$c pass $k $(same "$d/new$k.mesh" "$d/old$k.mesh")"
    m="$d/new$k.mesh"
  done
done
d="$W/linear2d_s_0.1"
for h in 0.004 0.002; do
  "$NEW" adapt "$W/linear2d/p0.mesh" --hsiz "$h" --hgrad 0 -o "$W/new_$h.mesh" -q
  "$OLD" adapt "$W/linear2d/p0.mesh" --hsiz "$h" --hgrad 0 -o "$W/old_$h.mesh" -q
  echo "uniform --hsiz $h $(same "$W/new_$h.mesh" "$W/old_$h.mesh")"
done
"$NEW" adapt "$d/new2.mesh" --metric "$d/m3.sol" -o "$W/new_g.mesh" -q
"$OLD" adapt "$d/new2.mesh" --metric "$d/m3.sol" -o "$W/old_g.mesh" -q
echo "linear2d:s=0.1 default --hgrad $(same "$W/new_g.mesh" "$W/old_g.mesh")"
