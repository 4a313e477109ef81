#!/usr/bin/env bash
# The 2D adaptation cases of ../shared/PEERS.md run through the independent harness in
# ../shared/bench (metric re-evaluated analytically on each new mesh, measured by evaluate.py),
# with `riemesh adapt` as the remesher. Prints the harness's table of the last pass per case.
#   bench/adapt2d_cases.sh [PASSES] [CASE ...]      (default: 5 passes, the cases below)
# Needs build/riemesh (scripts/build.sh; RIEMESH=path: another binary) and Debian's python3-numpy and time.
set -euo pipefail
cd "$(dirname "$0")/.."
H=$(cd ../shared/bench && pwd)
R=${RIEMESH:-$PWD/build/riemesh}
passes=${1:-5}
shift || true
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(linear2d polar2d polar2d-2 polar2d-mild "linear2d:h0=0.00001" \
                                  "linear2d:s=0.1" "polar2d:s=0.1")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for c in "${cases[@]}"; do
  # --hgrad 0: the UGAWG fields are prescribed exactly; gradation would change them.
  /usr/bin/python3 "$H/iterate.py" "$c" --workdir "$out/$c" --passes "$passes" --label "$c" \
    --cmd "$R adapt {mesh} --metric {sol} -o {out} -q --hgrad 0" >> "$out/results.jsonl"
done
/usr/bin/python3 "$H/summarize.py" "$out/results.jsonl" --last
