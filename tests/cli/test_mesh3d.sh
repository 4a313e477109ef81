#!/usr/bin/env bash
# riemesh mesh on a surface: the volume inside a closed surface (boundary recovered with reported
# Steiner points), or one clear error line for surface defects.
set -u
. "$(dirname "$0")/cli_lib.sh"

# The unit tetrahedron's surface, outward; its open version lacks the last triangle.
write_tet_surface() {  # FILE NUM-TRIANGLES
  {
    printf 'MeshVersionFormatted 2\nDimension 3\nVertices\n4\n'
    printf '0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n'
    printf 'Triangles\n%s\n' "$2"
    printf '1 3 2 1\n1 2 4 2\n1 4 3 3\n2 3 4 4\n' | head -n "$2"
    printf 'End\n'
  } >"$1"
}
write_tet_surface "$TMP/tet.mesh" 4
out=$("$R" mesh "$TMP/tet.mesh" -o "$TMP/tet_vol.mesh"); code=$?
if [ $code -eq 0 ] && [[ "$out" == *"4 vertices, 1 tetrahedra, 4 boundary triangles"* ]] &&
   "$R" check "$TMP/tet_vol.mesh" >/dev/null; then ok mesh3d-tet; else ko "mesh3d-tet: $code $out"; fi

write_tet_surface "$TMP/open.mesh" 3
expect_error mesh3d-open mesh "$TMP/open.mesh" -o "$TMP/open_vol.mesh"
expect_no_file mesh3d-open-no-output "$TMP/open_vol.mesh"
"$R" mesh "$TMP/open.mesh" -o "$TMP/x.mesh" 2>&1 | grep -q "3 edges on one triangle only (holes)" &&
  ok mesh3d-open-named || ko mesh3d-open-named

# elephant.mesh: every triangle is a Delaunay face, the volume is valid.
"$R" mesh -q "$SHARED/data/surf/elephant.mesh" -o "$TMP/elephant.mesh" &&
  "$R" check "$TMP/elephant.mesh" >/dev/null && ok mesh3d-elephant || ko mesh3d-elephant

# bunny.mesh: 128 triangles are not Delaunay faces; boundary recovery adds Steiner points on the
# surface, reported, and the volume is valid.
out=$("$R" mesh "$SHARED/data/surf/bunny.mesh" -o "$TMP/bunny.mesh"); code=$?
if [ $code -eq 0 ] && [[ "$out" =~ \ ([1-9][0-9]*)\ Steiner\ points\ \(([0-9]+)\ on\ edges,\ ([0-9]+)\ in\ faces,\ 0\ inside\) ]] &&
   [ $((BASH_REMATCH[2] + BASH_REMATCH[3])) -eq "${BASH_REMATCH[1]}" ] &&
   "$R" check "$TMP/bunny.mesh" >/dev/null; then ok mesh3d-bunny-recovered; else ko "mesh3d-bunny-recovered: $code $out"; fi
exit $fail
