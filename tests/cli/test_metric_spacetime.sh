#!/usr/bin/env bash
# riemesh metric combine --mode lp: the space-time Lp metric of two sub-intervals from |H|
# samples. The mean complexity per time step is N (within 5%), the complexities of the
# sub-intervals follow N_2/N_1 = (H_2/H_1)^(dp/(2p+d)) for proportional Hessians, the outputs are
# metrics riemesh adapt accepts, and bad combinations fail with one line.
set -u
source "$(dirname "$0")/cli_lib.sh"
D=$SHARED/data/formats
PY=/usr/bin/python3

# |H| samples as L∞ metrics c|H|/E: E = 1 on the first sub-interval, E = 1/4 (4 |H|) on the second.
"$R" metric hessian "$D/lshape.mesh" "$D/lshape.sol" --norm inf --tolerance 1 -o "$TMP/h1.sol" >/dev/null &&
  "$R" metric hessian "$D/lshape.mesh" "$D/lshape.sol" --norm inf --tolerance 0.25 -o "$TMP/h4.sol" >/dev/null &&
  ok samples || ko samples

out=$("$R" metric combine "$TMP/h1.sol" "$TMP/h1.sol" "$TMP/h4.sol" "$TMP/h4.sol" --mesh "$D/lshape.mesh" \
  --mode lp --norm 2 --complexity 2000 --intervals 2 -o "$TMP/m1.sol,$TMP/m2.sol" --json) &&
  ok lp-runs || ko "lp-runs: $out"
printf '%s' "$out" | $PY -c '
import json, sys
r = json.load(sys.stdin)
n1, n2 = r["interval_complexities"]
assert abs(r["complexity"] / 2000 - 1) < 0.05, r
assert abs((n1 + n2) / 2 / 2000 - 1) < 0.05, r
# d = 2, p = 2: N_2 / N_1 = 4^(4/6)
assert abs(n2 / n1 / 4 ** (4 / 6) - 1) < 0.01, (n2 / n1)
' && ok complexities-as-formula || ko "complexities-as-formula: $out"
"$R" adapt "$D/lshape.mesh" --metric "$TMP/m2.sol" -o "$TMP/a2.mesh" -q && ok adapt-on-lp-metric ||
  ko adapt-on-lp-metric

# Unequal time steps (3 steps on the first sub-interval, 1 on the second), integral in time.
out=$("$R" metric combine "$TMP/h1.sol" "$TMP/h1.sol" "$TMP/h1.sol" "$TMP/h1.sol" \
  --meshes "$D/lshape.mesh,$D/lshape.mesh" --mode lp --complexity 1000 --intervals 2 \
  --time integral --time-steps 3,1 -o "$TMP/m1.sol,$TMP/m2.sol" --json)
printf '%s' "$out" | $PY -c '
import json, sys
r = json.load(sys.stdin)
n1, n2 = r["interval_complexities"]
assert abs((3 * n1 + n2) / 4 / 1000 - 1) < 0.05, r
assert abs(n1 / n2 / 3 ** (-1 / 3) - 1) < 0.01, (n1 / n2)  # N_i ∝ n_i^(-d/(2p+d))
' && ok time-step-weights || ko "time-step-weights: $out"

"$R" metric combine -h | grep -q "N_st" && ok help-formula || ko help-formula
expect_error lp-no-complexity metric combine "$TMP/h1.sol" --mesh "$D/lshape.mesh" --mode lp -o "$TMP/x.sol"
expect_error lp-uneven metric combine "$TMP/h1.sol" "$TMP/h1.sol" "$TMP/h1.sol" --mesh "$D/lshape.mesh" \
  --mode lp --complexity 100 --intervals 2 -o "$TMP/x.sol,$TMP/y.sol"
expect_error lp-outputs metric combine "$TMP/h1.sol" "$TMP/h1.sol" --mesh "$D/lshape.mesh" \
  --mode lp --complexity 100 --intervals 2 -o "$TMP/x.sol"
expect_error bad-mode metric combine "$TMP/h1.sol" --mesh "$D/lshape.mesh" --mode union -o "$TMP/x.sol"
expect_no_file lp-no-output "$TMP/x.sol"
exit $fail
