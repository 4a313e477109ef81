#!/usr/bin/env bash
# riemesh metric calc: analytic results, JSON output, and every bad-input path (exit 2, one line).
set -u
R=${RIEMESH:?path to the riemesh binary}
fail=0
ok() { echo "ok   $1"; }
ko() { echo "FAIL $1"; fail=1; }

# expect_json NAME KEY EXPECTED TOL ARGS...: the JSON value at KEY (a python expression on j)
expect_json() {
  local name=$1 expr=$2 want=$3 tol=$4; shift 4
  local out
  out=$("$R" metric calc --json "$@" 2>&1) || { ko "$name: exit $? ($out)"; return; }
  if /usr/bin/python3 -c "import json,sys; j=json.loads(sys.argv[1]); v=$expr; w=$want; \
      import math; sys.exit(0 if all(abs(a-b)<=$tol for a,b in zip(v if isinstance(v,list) else [v], w if isinstance(w,list) else [w])) else 1)" "$out"; then
    ok "$name"
  else
    ko "$name: got $out"
  fi
}

# expect_error NAME ARGS...: exit code 2 and exactly one line on stderr, nothing on stdout
expect_error() {
  local name=$1; shift
  local out err code
  out=$("$R" metric calc "$@" 2>/tmp/riemesh_cli_err.$$); code=$?
  err=$(cat /tmp/riemesh_cli_err.$$); rm -f /tmp/riemesh_cli_err.$$
  if [ "$code" -eq 2 ] && [ -z "$out" ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ]; then
    ok "$name ($err)"
  else
    ko "$name: exit $code, stdout '$out', stderr '$err'"
  fi
}

# Log-Euclidean midpoint of diag(1,4) and diag(4,1): exp((log diag(1,4) + log diag(4,1))/2) = 2 I.
expect_json interp-log 'j["metric"]' '[2,0,2]' 1e-12 interp --scheme log --t 0.5 1,0,4 4,0,1
expect_json interp-log-sizes 'j["sizes"]' '[2**-0.5,2**-0.5]' 1e-12 interp --t 0.5 1,0,4 4,0,1
# Coefficient-linear midpoint: (5/2) I.
expect_json interp-linear 'j["metric"]' '[2.5,0,2.5]' 1e-12 interp --scheme linear 1,0,4 4,0,1
# t = 0 gives A for every scheme.
for s in linear iso-linear iso-geometric iso-harmonic simred-linear simred-geometric power log cholesky cholesky-geometric; do
  expect_json "interp-$s-t0" 'j["metric"]' '[3,1,2]' 1e-9 interp --scheme $s --t 0 3,1,2 1,0,5
done
# Intersection of diag(1,4) and diag(4,1): diag(4,4) (the smaller size in each axis).
expect_json intersect-2 'j["metric"]' '[4,0,4]' 1e-12 intersect 1,0,4 4,0,1
expect_json intersect-3d 'j["metric"]' '[4,0,4,0,0,9]' 1e-9 intersect 1,0,4,0,0,1 4,0,1,0,0,9
expect_json intersect-n-max-volume 'j["det"]' '16' 1e-5 intersect 1,0,4 4,0,1 2,0,2
# The unit equilateral triangle is unit and regular for the identity metric.
expect_json element-equilateral 'j["metric"]' '[1,0,1]' 1e-12 element 0,0 1,0 0.5,0.8660254037844386
# Right triangle (0,0),(2,0),(0,1): N = (2,0)(2,0)ᵀ + (0,1)(0,1)ᵀ + (-2,1)(-2,1)ᵀ = [[8,-2],[-2,2]],
# M = (3/2) N⁻¹ = (3/2)/12 [[2,2],[2,8]] = [[0.25,0.25],[0.25,1]].
expect_json element-right 'j["metric"]' '[0.25,0.25,1]' 1e-12 element 0,0 2,0 0,1
expect_json element-3d 'j["anisotropy"]' '1' 1e-9 element 0,0,0 1,0,0 0.5,0.8660254037844386,0 0.5,0.28867513459481287,0.816496580927726
expect_json length-2d 'j["length"]' '2' 1e-15 length --metric 4,0,1 1,0
expect_json length-3d 'j["length"]' '5' 1e-15 length --metric 9,0,16,0,0,1 1,1,0
expect_json directions-2d 'j["directions"][0]' '90' 1e-9 interp --t 0 4,0,1 4,0,1
expect_json anisotropy 'j["anisotropy"]' '10' 1e-9 interp --t 0 1,0,100 1,0,100

# Human-readable output mentions sizes and anisotropy.
if "$R" metric calc interp 1,0,4 4,0,1 | grep -q "anisotropy"; then ok text-output; else ko text-output; fi

expect_error wrong-count interp 1,0 4,0,1
expect_error mixed-dims interp 1,0,1 1,0,1,0,0,1
expect_error not-spd interp 1,2,1 1,0,1
expect_error nan interp nan,0,1 1,0,1
expect_error inf intersect 1,0,inf 1,0,1
expect_error t-nan interp --t nan 1,0,1 2,0,2  # printed NaN and `nan` in the JSON, exit 0
expect_error garbage interp 1,x,1 1,0,1
expect_error degenerate element 0,0 1,1 2,2
expect_error degenerate-3d element 0,0,0 1,0,0 0,1,0 1,1,0
expect_error point-dims element 0,0 1,0,0 0,1
expect_error length-dims length --metric 1,0,1 1,0,0
expect_error bad-scheme interp --scheme nope 1,0,1 1,0,1
expect_error t-range interp --t 2 1,0,1 1,0,1
expect_error one-metric intersect 1,0,1
expect_error no-op
# Answers near the ends of the doubles' range: computed, or refused (NaN and inf were printed).
out=$("$R" metric calc --json element 0,0 1e78,0 0,1e78)
[[ "$out" == '{"metric": [1e-156, 5.0000000000000002e-157, 1e-156],'* ]] && ok "element-1e78" || ko "element-1e78: $out"
out=$("$R" metric calc --json length --metric 1,0,4 1e300,0)
[ "$out" = '{"length": 1.0000000000000001e+300}' ] && ok "length-1e300" || ko "length-1e300: $out"
expect_error element-det-overflow element 0,0 1e-80,0 0,1e-80
exit $fail
