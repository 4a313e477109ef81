#!/usr/bin/env bash
# riemesh check and riemesh stats: exit codes, and stats --json values on a hand-made mesh.
set -u
. "$(dirname "$0")/cli_lib.sh"

# --- check -------------------------------------------------------------------------------------
out=$("$R" check "$SHARED/data/2d/naca0012.mesh"); code=$?
if [ $code -eq 0 ] && [[ "$out" == *": valid, planar"* ]]; then ok check-valid; else ko "check-valid: $code $out"; fi
"$R" check "$SHARED/data/vol/$(ls "$SHARED/data/vol" | grep -m1 '\.mesh$')" >/dev/null; code=$?
[ $code -eq 0 ] || [ $code -eq 1 ] && ok "check-volume-runs ($code)" || ko "check-volume-runs: $code"

# A truncated file: unreadable -> exit 2, one line.
head -c 60000 "$SHARED/data/2d/naca0012.mesh" >"$TMP/broken.mesh"
expect_error check-truncated check "$TMP/broken.mesh"
expect_error check-missing check "$TMP/none.mesh"
expect_error check-extension check "$TMP/mesh.txt"

# An inverted triangle (clockwise 1 3 2): invalid -> exit 1, the issue named with a location.
write_two_triangles "$TMP/two.mesh"
sed 's/^1 2 3 1$/1 3 2 1/' "$TMP/two.mesh" >"$TMP/inverted.mesh"
out=$("$R" check "$TMP/inverted.mesh"); code=$?
if [ $code -eq 1 ] && [[ "$out" == *"INVALID"* ]] && [[ "$out" == *"inverted element: 1 (first: triangle 1 at ("* ]]; then
  ok check-inverted
else
  ko "check-inverted: $code $out"
fi
"$R" check "$TMP/two.mesh" >/dev/null && ok check-two-triangles || ko check-two-triangles

# Surfaces: triangles crossing each other make a surface invalid (a triangle in z = 0 and one
# piercing it), named with the first pair; moved apart, the two are valid.
write_pierced() {  # FILE X0 X1 (x of the second triangle's vertices)
  printf 'MeshVersionFormatted 2\nDimension 3\nVertices\n6\n0 0 0 1\n1 0 0 1\n0 1 0 1\n' >"$1"
  printf '%s 0.2 -0.5 1\n%s 0.2 0.5 1\n%s 0.4 0.5 1\n' "$2" "$3" "$2" >>"$1"
  printf 'Triangles\n2\n1 2 3 1\n4 5 6 2\nEnd\n' >>"$1"
}
write_pierced "$TMP/apart.mesh" 2.2 2.4
out=$("$R" check "$TMP/apart.mesh"); code=$?
if [ $code -eq 0 ] && [[ "$out" == *": valid, surface"* ]]; then ok check-surface-valid; else ko "check-surface-valid: $code $out"; fi
write_pierced "$TMP/pierced.mesh" 0.2 0.4
out=$("$R" check "$TMP/pierced.mesh"); code=$?
if [ $code -eq 1 ] && [[ "$out" == *"INVALID"* ]] &&
  [[ "$out" == *"self-intersection: 1 pairs of triangles (first: triangles 1 and 2 at ("* ]]; then
  ok check-surface-crossing
else
  ko "check-surface-crossing: $code $out"
fi
# gmsh's two boxes listed as one surface (tests/data): their 20 shared edges are on 3 triangles,
# where the regions meet: noted, valid (riemesh mesh takes it).
two_boxes="$(dirname "$0")/../data/two_boxes_gmsh.mesh"
out=$("$R" check "$two_boxes"); code=$?
if [ $code -eq 0 ] && [[ "$out" == *": valid, surface"* ]] &&
  [[ "$out" == *"note, edges on 3 or more triangles (where regions meet): 20 (first: triangle "* ]]; then
  ok check-surface-of-two-regions
else
  ko "check-surface-of-two-regions: $code $out"
fi

# A misspelt keyword (`Triangle`) skipped its section without a word (QA hunt 5 F8): a note
# names it and its line; FreeFem's dialect keywords (Identifier, Geometry, ...) stay silent.
sed 's/^Triangles/Triangle/' "$SHARED/data/2d/naca0012.mesh" >"$TMP/misspelt.mesh"
err=$("$R" check "$TMP/misspelt.mesh" 2>&1 >/dev/null)
[[ "$err" == *"misspelt.mesh: 1 unknown keyword skipped with its data: Triangle (line "* ]] &&
  ok check-unknown-keyword-noted || ko "check-unknown-keyword-noted: $err"
err=$("$R" check "$SHARED/data/dialects/aile_freefem.mesh" 2>&1 >/dev/null)
[ -z "$err" ] && ok check-freefem-keywords-silent || ko "check-freefem-keywords-silent: $err"

# --- stats --json on two right triangles ------------------------------------------------------
# Areas ½ each; Euclidean mean ratio 4√3·½/(1+1+2) = √3/2 (bin [0.8, 0.9)). With M = diag(4, 1):
# lengths 2 (x edges), 1 (y edges), √5 (diagonal) -> 2 of 5 in [1/√2, √2]; histogram bins
# [1, √2): 2 and [2, 2√2): 3; metric quality 4√3·sqrt(det M)·½/(4+1+5) = 0.4√3 (bin [0.6, 0.7)).
write_metric "$TMP/m.sol" 4 "4 0 1" "4 0 1" "4 0 1" "4 0 1"
json=$("$R" stats --json "$TMP/two.mesh" --metric "$TMP/m.sol"); code=$?
if [ $code -ne 0 ]; then ko "stats-json: exit $code"; fi
check_json() {  # NAME PYTHON-BOOLEAN-EXPRESSION-ON-j
  if /usr/bin/python3 -c "import json,sys,math; j=json.loads(sys.argv[1]); sys.exit(0 if ($2) else 1)" "$json"; then
    ok "$1"; else ko "$1: $2 on $json"; fi
}
[ "$(printf '%s\n' "$json" | wc -l)" -eq 1 ] && ok stats-json-one-line || ko stats-json-one-line
check_json stats-keys 'set(j) == {"file","dim","kind","valid","counts","refs","measure","quality","metric"}'
# A triangle of coordinates near 1e308: its measure overflows; null, not `inf` or `-nan` (not JSON).
printf 'MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 0\n1e308 0 0 0\n0 1e308 0 0\nTriangles\n1\n1 2 3 0\nEnd\n' >"$TMP/huge.mesh"
"$R" stats "$TMP/huge.mesh" --json | /usr/bin/python3 -c "import json,sys; json.load(sys.stdin)" &&
  ok stats-json-overflow-is-null || ko stats-json-overflow-is-null
check_json stats-kind 'j["dim"] == 2 and j["kind"] == "planar" and j["valid"] is True'
check_json stats-counts 'j["counts"] == {"vertices":4,"edges":5,"triangles":2,"tetrahedra":0,"boundary_edges":4,"boundary_triangles":0,"corners":0,"ridges":0,"required_vertices":0}'
check_json stats-refs 'j["refs"] == {"vertices":[1],"edges":[1,2,3,4],"triangles":[1,2],"tetrahedra":[]}'
check_json stats-measure 'j["measure"] == {"min":0.5,"max":0.5,"total":1.0}'
check_json stats-quality 'all(abs(j["quality"][k] - math.sqrt(3)/2) < 1e-15 for k in ("min","mean","max"))'
check_json stats-quality-hist 'j["quality"]["histogram"]["counts"] == [0]*8+[2,0] and len(j["quality"]["histogram"]["edges"]) == 11'
check_json stats-length 'abs(j["metric"]["edge_length"]["min"]-1) < 1e-14 and abs(j["metric"]["edge_length"]["max"]-math.sqrt(5)) < 1e-14 and abs(j["metric"]["edge_length"]["mean"]-(6+math.sqrt(5))/5) < 1e-14'
check_json stats-length-hist 'j["metric"]["edge_length"]["histogram"]["counts"] == [0,0,0,0,0,2,0,3,0,0]'
check_json stats-length-edges 'abs(j["metric"]["edge_length"]["histogram"]["edges"][4] - 2**-0.5) < 1e-15 and j["metric"]["edge_length"]["histogram"]["edges"][0] == 0'
check_json stats-unit-fraction 'j["metric"]["edge_length"]["unit_fraction"] == 0.4'
check_json stats-metric-quality 'abs(j["metric"]["quality"]["min"] - 0.4*math.sqrt(3)) < 1e-14 and j["metric"]["quality"]["histogram"]["counts"][6] == 2'
# Sizes, one per vertex (h = 0.5), are the metric I/h² = 4 I, as adapt --metric reads them (they
# were refused: "no symmetric tensor field"): lengths 2 and 2√2, as from the tensors "4 0 4".
printf 'MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n4\n1 1\n0.5\n0.5\n0.5\n0.5\nEnd\n' >"$TMP/sizes.sol"
write_metric "$TMP/m4.sol" 4 "4 0 4" "4 0 4" "4 0 4" "4 0 4"
json=$("$R" stats --json "$TMP/two.mesh" --metric "$TMP/sizes.sol")
check_json stats-metric-sizes 'j["metric"]["edge_length"]["min"] == 2 and abs(j["metric"]["edge_length"]["max"] - 2*math.sqrt(2)) < 1e-14'
[ -n "$json" ] && [ "$(printf '%s' "$json" | sed 's/"file": "[^"]*"//')" = \
  "$("$R" stats --json "$TMP/two.mesh" --metric "$TMP/m4.sol" | sed 's/"file": "[^"]*"//')" ] &&
  ok stats-metric-sizes-as-tensors || ko stats-metric-sizes-as-tensors
# A subnormal tensor (1e-310) is out of range at its vertex, not "not positive definite" (and
# "metric at vertex 2: metric ..."); a subnormal off-diagonal is negligible (it gave NaN).
write_metric "$TMP/sub.sol" 4 "1 0 1" "1e-310 0 1e-310" "1 0 1" "1 0 1"
expect_error_matching stats-metric-subnormal "sub.sol: vertex 2: metric out of range: a size of 1e+155" \
  stats "$TMP/two.mesh" --metric "$TMP/sub.sol"
write_metric "$TMP/sub_off.sol" 4 "1 0 1" "1 1e-310 1" "1 0 1" "1 0 1"
"$R" stats "$TMP/two.mesh" --metric "$TMP/sub_off.sol" >/dev/null && ok stats-metric-subnormal-off-diagonal ||
  ko stats-metric-subnormal-off-diagonal
json=$("$R" stats --json "$TMP/two.mesh")
check_json stats-no-metric-key '"metric" not in j'
json=$("$R" stats --json "$TMP/inverted.mesh")
check_json stats-inverted 'j["valid"] is False and j["measure"]["min"] == -0.5 and j["quality"]["min"] < 0'

# Real data: the L-shape with its metric, text and JSON.
json=$("$R" stats --json "$SHARED/data/formats/lshape.mesh" --metric "$SHARED/data/formats/lshape_metric.sol")
check_json stats-lshape 'j["counts"]["vertices"] == 372 and sum(j["metric"]["edge_length"]["histogram"]["counts"]) == j["counts"]["edges"] and 0 <= j["metric"]["edge_length"]["unit_fraction"] <= 1'
"$R" stats "$SHARED/data/2d/naca0012.mesh" | grep -q "quality (Euclidean)" && ok stats-text || ko stats-text

# --plot: a PNG of the histograms.
"$R" stats "$TMP/two.mesh" --metric "$TMP/m.sol" --plot "$TMP/h.png" >/dev/null
[ "$(head -c 8 "$TMP/h.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] && ok stats-plot || ko stats-plot

# --- bad inputs: exit 2, one line, no output ----------------------------------------------------
write_metric "$TMP/short.sol" 3 "4 0 1" "4 0 1" "4 0 1"
expect_error stats-metric-count stats "$TMP/two.mesh" --metric "$TMP/short.sol"
write_metric "$TMP/indefinite.sol" 4 "4 0 1" "4 0 1" "1 2 1" "4 0 1"
expect_error stats-metric-not-spd stats --json "$TMP/two.mesh" --metric "$TMP/indefinite.sol"
grep -q "vertex 3" "$TMP/err" && ok stats-metric-names-vertex || ko "stats-metric-names-vertex: $(cat "$TMP/err")"
expect_error stats-missing stats "$TMP/none.mesh"
expect_error stats-missing-metric stats "$TMP/two.mesh" --metric "$TMP/none.sol"
expect_error stats-plot-extension stats "$TMP/two.mesh" --plot "$TMP/h.jpg"
expect_no_file stats-plot-extension-no-file "$TMP/h.jpg"
expect_error stats-bad-width stats "$TMP/two.mesh" --plot "$TMP/w.png" --width 3
expect_no_file stats-bad-width-no-file "$TMP/w.png"
expect_error stats-truncated stats --json "$TMP/broken.mesh"

exit $fail
