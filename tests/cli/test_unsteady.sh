#!/usr/bin/env bash
# riemesh unsteady: the fixed-point loop over time sub-intervals on a moving front. The JSON
# output has the documented keys, the error falls with the complexity, four sub-intervals beat
# one mesh for all time at the same mean complexity, the Lp mode's mean metric complexity is N
# (within 5%), the output is deterministic, and bad options fail with one line.
set -u
source "$(dirname "$0")/cli_lib.sh"
PY=/usr/bin/python3

args=(unsteady --complexities 300,1200 --intervals 4 --samples 3 --iterations 2 --json)
"$R" "${args[@]}" >"$TMP/a.json" && ok runs || ko runs
printf '%s' "$(cat "$TMP/a.json")" | $PY -c '
import json, sys
r = json.load(sys.stdin)
m, s = r["multi"], r["single"]
assert len(m) == 2 and len(s) == 2
assert m[1]["error"] < 0.6 * m[0]["error"], m
for a, b in zip(m, s):
    assert a["intervals"] == 4 and b["intervals"] == 1
    assert a["error"] < b["error"], (a, b)
    assert abs(a["metric_complexity"] / a["complexity"] - 1) < 0.05, a
    assert a["total_vertices"] >= 4 * 0.5 * a["complexity"]
assert "multi" in r["slopes"] and "single" in r["slopes"]
' && ok error-falls-and-beats-one-mesh || ko "error-falls-and-beats-one-mesh: $(cat "$TMP/a.json")"

"$R" "${args[@]}" >"$TMP/b.json"
strip() { $PY -c 'import json,sys; r=json.load(open(sys.argv[1]))
for k in ("multi","single"):
    for s in r[k]: s.pop("seconds")
print(json.dumps(r, sort_keys=True))' "$1"; }
[ "$(strip "$TMP/a.json")" = "$(strip "$TMP/b.json")" ] && ok deterministic || ko deterministic

"$R" unsteady --function moving-circle --complexities 300 --intervals 2 --samples 2 \
  --iterations 1 --combine intersect --no-single | grep -q "fitted slope" && ok intersect-text ||
  ko intersect-text
"$R" unsteady -h | grep -q "space-time Lp" && ok help || ko help

expect_error bad-combine unsteady --combine union
expect_error bad-function unsteady --function nope
expect_error bad-intervals unsteady --intervals 0
exit $fail
