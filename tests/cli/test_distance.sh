#!/usr/bin/env bash
# riemesh distance: two-sided and one-sided figures on hand-made surfaces, --json, errors.
set -u
. "$(dirname "$0")/cli_lib.sh"

# write_square PATH Z SIZE: the square [0,SIZE]² at height Z as two triangles, in 3D.
write_square() {
  cat >"$1" <<MESH
MeshVersionFormatted 2
Dimension 3
Vertices
4
0 0 $2 0
$3 0 $2 0
$3 $3 $2 0
0 $3 $2 0
Triangles
2
1 2 3 1
1 3 4 1
End
MESH
}
write_square "$TMP/a.mesh" 0 1
write_square "$TMP/b.mesh" 0.25 1
write_square "$TMP/big.mesh" 0 2

check_json() {  # NAME PYTHON-BOOLEAN-EXPRESSION-ON-j
  if /usr/bin/python3 -c "import json,sys,math; j=json.loads(sys.argv[1]); sys.exit(0 if ($2) else 1)" "$json"; then
    ok "$1"; else ko "$1: $2 on $json"; fi
}

# Parallel squares 0.25 apart: every sample is 0.25 away, both ways.
json=$("$R" distance "$TMP/a.mesh" "$TMP/b.mesh" --json); code=$?
[ $code -eq 0 ] && ok distance-exit || ko "distance-exit: $code"
check_json parallel-two-sided "abs(j['hausdorff'] - 0.25) < 1e-12"
check_json parallel-a-to-b "abs(j['a_to_b']['max'] - 0.25) < 1e-12 and abs(j['a_to_b']['mean'] - 0.25) < 1e-12"
check_json parallel-samples "j['a_to_b']['samples'] == 2 * 15 and j['lattice_order'] == 4"

# [0,1]² inside [0,2]²: A -> B is 0, B -> A is √2 (the far corner), so two-sided √2.
json=$("$R" distance "$TMP/a.mesh" "$TMP/big.mesh" --json --samples 2)
check_json nested-one-sided "j['a_to_b']['max'] == 0 and abs(j['b_to_a']['max'] - math.sqrt(2)) < 1e-12"
check_json nested-where "abs(j['b_to_a']['where'][0] - 2) < 1e-12 and abs(j['b_to_a']['where'][1] - 2) < 1e-12"
check_json nested-samples "j['a_to_b']['samples'] == 2 * 6"

# Text output: three lines, the last one the two-sided figure.
out=$("$R" distance "$TMP/a.mesh" "$TMP/b.mesh")
if [ "$(printf '%s\n' "$out" | wc -l)" -eq 3 ] && [[ "$out" == *"Hausdorff (two-sided): 2.500000e-01"* ]]; then
  ok distance-text
else
  ko "distance-text: $out"
fi

# A real surface against itself: zero.
json=$("$R" distance "$SHARED/data/surf/rotor.mesh" "$SHARED/data/surf/rotor.mesh" --json)
check_json rotor-self "j['hausdorff'] < 1e-12"

expect_error distance-missing distance "$TMP/a.mesh" "$TMP/none.mesh"
# A planar mesh is the surface z = 0: the square at height 0.25 is 0.25 from aile's triangles
# where they overlap, and aile's far points are far.
json=$("$R" distance "$TMP/b.mesh" "$SHARED/data/2d/aile.mesh" --json)
check_json planar-lifted "j['a_to_b']['max'] >= 0.25 and j['b_to_a']['max'] > 1"
printf 'MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 0 1 0\nEdges\n1\n1 2 1\nEnd\n' >"$TMP/edge.mesh"
expect_error distance-no-triangles distance "$TMP/a.mesh" "$TMP/edge.mesh"
expect_error distance-samples distance "$TMP/a.mesh" "$TMP/b.mesh" --samples 0
# Coordinates near 1e308: the distances overflowed (inf, -nan%, exit 0); refused by place.
printf 'MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 0\n1e308 0 0 0\n0 1e308 0 0\nTriangles\n1\n1 2 3 0\nEnd\n' >"$TMP/huge.mesh"
expect_error_matching distance-huge-coordinates "huge.mesh: vertex 2: coordinate 1e+308 is out of range" \
  distance "$TMP/huge.mesh" "$TMP/a.mesh"
exit $fail
