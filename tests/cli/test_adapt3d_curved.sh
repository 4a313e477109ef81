#!/usr/bin/env bash
# riemesh adapt on a volume with a curved boundary (issue #7): a cylinder of 24 flat facets
# refined 10x in its normal direction (size 0.3 -> 0.03) stays a cylinder (side vertices within 1e-3 of the
# radius), the output is valid with its 3 refs, reached through an intermediate field (staged
# approach; --approach 0: at once); --nosurf keeps the side vertices; bad inputs (--hausd <= 0,
# --approach in (0, 1]) exit 2 with one line and no output.
set -u
source "$(dirname "$0")/cli_lib.sh"

# The cylinder r = 1, z in [0, 1]: 24 facets, 2 layers of prisms (3 tets each), refs side 1,
# bottom 2, top 3; and a metric of size 0.3 along the circle and the axis, 0.3 -> 0.03 radially.
/usr/bin/python3 "$(dirname "$0")/../../bench/cylinder_mesh.py" "$TMP/cyl.mesh" "$TMP/cyl.sol" 0.03

# Side vertices (in a triangle of ref 1): count and largest |radius - 1|.
side() { /usr/bin/python3 "$(dirname "$0")/../../bench/cylinder_mesh.py" --side "$1"; }
tri_refs() {
  "$R" stats "$1" --json | /usr/bin/python3 -c \
    'import json,sys; j=json.load(sys.stdin); print(sorted(int(k) for k in j["refs"]["triangles"]))' 2>/dev/null
}

"$R" adapt "$TMP/cyl.mesh" --metric "$TMP/cyl.sol" -o "$TMP/out.mesh" 2>"$TMP/passes" && ok adapt3d-curved || ko adapt3d-curved
# The input's edges are ~10 long in the metric: one intermediate field first (--approach 4).
grep -q "^pass  1 (toward the metric: stage 1/2)" "$TMP/passes" && grep -q "stage 2/2" "$TMP/passes" &&
  ok curved-staged || ko "curved-staged: $(head -2 "$TMP/passes")"
"$R" adapt "$TMP/cyl.mesh" --metric "$TMP/cyl.sol" -o "$TMP/direct.mesh" --approach 0 --passes 2 2>"$TMP/passes" &&
  ! grep -q stage "$TMP/passes" && "$R" check "$TMP/direct.mesh" >/dev/null && ok curved-direct || ko curved-direct
"$R" check "$TMP/out.mesh" >/dev/null && ok curved-valid || ko curved-valid
[ "$(tri_refs "$TMP/out.mesh")" = "[1, 2, 3]" ] && ok curved-refs || ko "curved-refs: $(tri_refs "$TMP/out.mesh")"
read -r n err <<<"$(side "$TMP/out.mesh")"
# (The side is 6.3 in area, sizes 0.3 along it: ~160 unit triangles, ~80 vertices; the input has 72.)
/usr/bin/python3 -c "import sys; sys.exit(0 if $n > 100 and $err < 1e-3 else 1)" &&
  ok "curved-on-cylinder ($n side vertices, max |r - 1| = $err)" || ko "curved-on-cylinder: $n $err"

# --nosurf: the 72 side vertices of the input, at their place.
"$R" adapt "$TMP/cyl.mesh" --metric "$TMP/cyl.sol" -o "$TMP/ns.mesh" -q --nosurf --passes 2 &&
  [ "$(side "$TMP/ns.mesh" | cut -d" " -f1)" = 72 ] && ok curved-nosurf || ko "curved-nosurf: $(side "$TMP/ns.mesh")"

expect_error curved-hausd-zero adapt "$TMP/cyl.mesh" --metric "$TMP/cyl.sol" --hausd 0 -o "$TMP/bad.mesh"
expect_no_file curved-hausd-zero-no-output "$TMP/bad.mesh"
expect_error curved-approach-below-one adapt "$TMP/cyl.mesh" --metric "$TMP/cyl.sol" --approach 0.5 -o "$TMP/bad.mesh"
expect_no_file curved-approach-no-output "$TMP/bad.mesh"
expect_error curved-hausd-negative adapt "$TMP/cyl.mesh" --hsiz 0.2 --hausd -1 -o "$TMP/bad.mesh"
exit $fail
