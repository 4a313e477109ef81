#!/usr/bin/env bash
# riemesh loop: a tiny loop prints its table and slopes; --json has the documented keys and falling
# errors; --plot writes a PNG; bad options exit 2 with one line.
set -u
source "$(dirname "$0")/cli_lib.sh"

out=$("$R" loop --function tanh --complexities 150,300 --iterations 1 --uniform) &&
  ok loop-text || ko loop-text
[[ "$out" == *"fitted slope, adapted"* && "$out" == *"fitted slope, uniform"* ]] &&
  ok loop-text-slopes || ko "loop-text-slopes: $out"

"$R" loop --function boundary-layer --complexities 150,300 --iterations 2 --json >"$TMP/l.json" &&
  /usr/bin/python3 - "$TMP/l.json" <<'PY' && ok loop-json || ko loop-json
import json, sys
j = json.load(open(sys.argv[1]))
assert j["function"] == "boundary-layer" and j["iterations"] == 2 and j["norm"] == 2
assert set(j) >= {"formula", "adapted", "uniform", "slopes"}
a = j["adapted"]
assert [s["complexity"] for s in a] == [150, 300]
for s in a:
    assert set(s) >= {"vertices", "triangles", "l1", "l2", "linf", "metric_complexity", "converged"}
assert a[1]["l2"] < a[0]["l2"] and a[1]["vertices"] > a[0]["vertices"]
assert j["uniform"] == [] and set(j["slopes"]["adapted"]) == {"l1", "l2", "linf"}
assert j["slopes"]["adapted"]["l2"] < 0 and j["slopes"]["uniform"]["l2"] is None
PY

"$R" loop --function multiscale --complexities 150,300 --iterations 1 --plot "$TMP/e.png" >/dev/null &&
  [ "$(head -c 8 "$TMP/e.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] &&
  ok loop-plot || ko loop-plot

expect_error unknown-function loop --function nope
expect_error bad-norm loop --norm 0.5
expect_error bad-complexities loop --complexities 100,abc
expect_error bad-iterations loop --iterations 0
expect_error bad-plot loop --complexities 100 --plot "$TMP/e.bmp"
expect_no_file bad-plot-file "$TMP/e.bmp"
# Checked before anything is printed (the header came first), lists without empty items, a fit
# range of at least two complexities (the slopes printed "nan").
expect_error_matching loop-hgrad-before-header "^riemesh: error: --hgrad must be 0 (off) or a ratio > 1, got 0.5$" \
  loop --complexities 100 --hgrad 0.5
expect_error_matching loop-trailing-comma "'100,' ends with a comma" loop --complexities 100,
expect_error_matching loop-double-comma "'100,,200' has two commas in a row" loop --complexities 100,,200
expect_error_matching loop-fit-from-beyond "^riemesh: error: --fit-from 5000 leaves fewer than two complexities" \
  loop --complexities 100,200 --fit-from 5000
exit $fail
