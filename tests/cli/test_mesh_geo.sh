#!/usr/bin/env bash
# riemesh mesh on Gmsh .geo geometries (issue #8: parametric curves): the square with a circular
# hole and the NACA 0012 in a disc of tests/data/geo mesh into valid meshes whose boundary nodes
# lie on the exact curves, with the physical groups' refs; --hsiz refines; Gmsh and meshio read the
# output; bad geometries give one-line errors naming the file and line, and no output.
set -u
. "$(dirname "$0")/cli_lib.sh"
GEO="$(dirname "$0")/../data/geo"

"$R" mesh -h | grep -q -- "Gmsh .geo" && ok "help" || ko "help"

summary() {  # summary MESH: refs of triangles and edges, and the largest |r - R| over the vertices
  /usr/bin/python3 - "$@" <<'PY'
import sys, meshio, numpy as np
m = meshio.read(sys.argv[1])
tri = [c for c in m.cells if c.type == "triangle"][0]
ref = lambda t: sorted(set(int(r) for r in np.concatenate([d for c, d in zip(m.cells, m.cell_data["medit:ref"]) if c.type == t])))
cx, cy, radius = map(float, sys.argv[2:5])
xy = m.points[:, :2]
r = np.hypot(xy[:, 0] - cx, xy[:, 1] - cy)
near = np.abs(r - radius) < 0.05 * radius
print(ref("triangle"), ref("line"), int(near.sum()), float(np.max(np.abs(r[near] - radius))))
PY
}

# Square with a hole of radius 0.2 at (0.5, 0.5): triangle ref 3, edge refs 1 (sides) and 2
# (circle), every vertex near the circle on it.
"$R" mesh "$GEO/square_hole.geo" -o "$TMP/sq.mesh" -q >"$TMP/out" &&
  grep -q "1 region, 1 hole" "$TMP/out" && "$R" check "$TMP/sq.mesh" >/dev/null &&
  ok "square-hole ($(cat "$TMP/out"))" || ko "square-hole"
s=$(summary "$TMP/sq.mesh" 0.5 0.5 0.2)
/usr/bin/python3 -c "import sys; a=sys.argv[1]; assert a.startswith('[3] [1, 2] '), a; n, d = a.split()[-2:]; assert int(n) >= 16 and float(d) < 1e-12, a" "$s" &&
  ok "square-hole-on-circle ($s)" || ko "square-hole-on-circle ($s)"

# --hsiz: more triangles when smaller.
tris() { "$R" stats --json "$1" | /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)['counts']['triangles'])"; }
"$R" mesh "$GEO/square_hole.geo" -o "$TMP/sq1.mesh" --hsiz 0.1 -q >/dev/null &&
  "$R" mesh "$GEO/square_hole.geo" -o "$TMP/sq2.mesh" --hsiz 0.02 -q >/dev/null &&
  [ "$(tris "$TMP/sq1.mesh")" -lt "$(tris "$TMP/sq2.mesh")" ] &&
  [ "$(tris "$TMP/sq2.mesh")" -gt 3000 ] && ok "hsiz ($(tris "$TMP/sq1.mesh") < $(tris "$TMP/sq2.mesh"))" || ko "hsiz"

# NACA 0012 in a disc of radius 5 centred at (0.5, 0): far-field nodes on the circle, refs of the
# physical groups (fluid 1; farfield 1, wall 2), Gmsh reads the output.
"$R" mesh "$GEO/naca0012.geo" -o "$TMP/naca.mesh" -q >"$TMP/out" &&
  "$R" check "$TMP/naca.mesh" >/dev/null && ok "naca ($(cat "$TMP/out"))" || ko "naca"
s=$(summary "$TMP/naca.mesh" 0.5 0 5)
/usr/bin/python3 -c "import sys; a=sys.argv[1]; assert a.startswith('[1] [1, 2] '), a; n, d = a.split()[-2:]; assert int(n) >= 30 and float(d) < 1e-12, a" "$s" &&
  ok "naca-far-field-on-circle ($s)" || ko "naca-far-field-on-circle ($s)"
if command -v gmsh >/dev/null; then
  "$R" mesh "$GEO/naca0012.geo" -o "$TMP/naca.msh" -q >/dev/null &&
    gmsh "$TMP/naca.msh" -0 -o "$TMP/naca-gmsh.msh" >/dev/null 2>&1 && ok "gmsh-reads-output" || ko "gmsh-reads-output"
fi

# Options that do not apply, and bad geometries: one line naming file and line, no output.
expect_error geo-metric mesh "$GEO/square_hole.geo" -o "$TMP/o1.mesh" --metric "$TMP/none.sol"
expect_error_matching geo-no-holes "--metric, --hole and --no-holes apply to a domain .mesh" mesh "$GEO/square_hole.geo" -o "$TMP/o1.mesh" --no-holes
printf 'Point(1) = {0, 0, 0};\nPoint(2) = {1, 0, 0};\nLine(1) = {1, 2};\nExtrude {0, 1, 0} { Curve{1}; }\n' >"$TMP/extrude.geo"
expect_error geo-unsupported mesh "$TMP/extrude.geo" -o "$TMP/o2.mesh"
"$R" mesh "$TMP/extrude.geo" -o "$TMP/o2.mesh" 2>&1 | grep -q "extrude.geo:4: 'Extrude' is not supported" &&
  ok "geo-unsupported-names-line" || ko "geo-unsupported-names-line"
expect_no_file geo-unsupported-no-file "$TMP/o2.mesh"
cat >"$TMP/open.geo" <<'GEO'
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3};
Curve Loop(1) = {1, 2};
Plane Surface(1) = {1};
GEO
expect_error geo-open-loop mesh "$TMP/open.geo" -o "$TMP/o3.mesh"
"$R" mesh "$TMP/open.geo" -o "$TMP/o3.mesh" 2>&1 | grep -q "open.geo:3: Curve Loop 1 is not closed" &&
  ok "geo-open-loop-names-line" || ko "geo-open-loop-names-line"
expect_no_file geo-open-loop-no-file "$TMP/o3.mesh"
printf 'Point(1) = {0, 0, 0};\nLine(1) = {1, 2};\n' >"$TMP/undefined.geo"
expect_error geo-undefined-point mesh "$TMP/undefined.geo" -o "$TMP/o4.mesh"
# -v 1: each pass line (with the fraction of lengths in band) and its detail line.
"$R" mesh "$GEO/naca0012.geo" -o "$TMP/v.mesh" -v 1 2>&1 |
  grep -Eq "^ +[0-9]+ splits [0-9]+ collapses [0-9]+ swaps [0-9]+ moves .* q mean [0-9.]+$" &&
  "$R" mesh "$GEO/naca0012.geo" -o "$TMP/v.mesh" 2>&1 | grep -q "^pass  1: .* lengths in \[1/√2, √2\] [0-9.]*%" &&
  ok "geo-verbose" || ko "geo-verbose"
# A size far too small (a mistyped lc): refused before the curves are meshed (it took ~10 s to
# mesh 2.8 M boundary nodes first), naming the surface's line; no output.
sed 's/lc = 0.05/lc = 1e-9/' "$GEO/square_hole.geo" >"$TMP/tiny.geo"
grep -q "lc = 1e-9" "$TMP/tiny.geo" || ko "geo-tiny-lc: the test geometry has no 'lc = 0.05'"
expect_error geo-tiny-lc mesh "$TMP/tiny.geo" -o "$TMP/o5.mesh"
"$R" mesh "$TMP/tiny.geo" -o "$TMP/o5.mesh" 2>&1 | grep -Eq "tiny.geo:[0-9]+: Plane Surface [0-9]+: its sizes \(at most [0-9.e+-]+\) ask for more than 1e\+08 vertices" &&
  ok "geo-tiny-lc-names-surface" || ko "geo-tiny-lc-names-surface"
expect_no_file geo-tiny-lc-no-file "$TMP/o5.mesh"

# Regions that lie in no Plane Surface (a hole inside a hole of the same surface) or in two (a
# surface inside another that does not list it as a hole) were meshed with a made-up ref or the
# first surface's, silently.
cat >"$TMP/nested.geo" <<'GEO'
Point(1)={0,0,0,0.4}; Point(2)={4,0,0,0.4}; Point(3)={4,4,0,0.4}; Point(4)={0,4,0,0.4};
Point(5)={1,1,0,0.4}; Point(6)={3,1,0,0.4}; Point(7)={3,3,0,0.4}; Point(8)={1,3,0,0.4};
Point(9)={1.5,1.5,0,0.2}; Point(10)={2.5,1.5,0,0.2}; Point(11)={2.5,2.5,0,0.2}; Point(12)={1.5,2.5,0,0.2};
Line(1)={1,2}; Line(2)={2,3}; Line(3)={3,4}; Line(4)={4,1};
Line(5)={5,6}; Line(6)={6,7}; Line(7)={7,8}; Line(8)={8,5};
Line(9)={9,10}; Line(10)={10,11}; Line(11)={11,12}; Line(12)={12,9};
Curve Loop(1)={1:4}; Curve Loop(2)={5:8}; Curve Loop(3)={9:12};
Plane Surface(1)={1,2,3};
GEO
expect_error_matching geo-hole-in-hole "nested.geo: the region near (.*) lies in no Plane Surface" \
  mesh "$TMP/nested.geo" -o "$TMP/o6.mesh" -q
cat >"$TMP/inside.geo" <<'GEO'
Point(1)={0,0,0,0.4}; Point(2)={4,0,0,0.4}; Point(3)={4,4,0,0.4}; Point(4)={0,4,0,0.4};
Point(5)={1,1,0,0.4}; Point(6)={2,1,0,0.4}; Point(7)={2,2,0,0.4}; Point(8)={1,2,0,0.4};
Line(1)={1,2}; Line(2)={2,3}; Line(3)={3,4}; Line(4)={4,1};
Line(5)={5,6}; Line(6)={6,7}; Line(7)={7,8}; Line(8)={8,5};
Curve Loop(1)={1:4}; Curve Loop(2)={5:8}; Plane Surface(1)={1}; Plane Surface(2)={2};
Physical Surface(1)={1}; Physical Surface(2)={2};
GEO
expect_error_matching geo-surface-inside-surface \
  "inside.geo: Plane Surface 1 and Plane Surface 2 overlap near" mesh "$TMP/inside.geo" -o "$TMP/o7.mesh" -q
expect_no_file geo-overlap-no-file "$TMP/o7.mesh"
# A hole touching its outer loop at one point (its first node): it was called outside.
cat >"$TMP/touch.geo" <<'GEO'
Point(1)={0,0,0,0.1}; Point(2)={1,0,0,0.1}; Point(3)={1,1,0,0.1}; Point(4)={0,1,0,0.1};
Point(5)={0.5,0.3,0,0.1}; Point(6)={0.8,0.5,0,0.1};
Line(1)={1,2}; Line(2)={2,3}; Line(3)={3,4}; Line(4)={4,1};
Line(5)={2,5}; Line(6)={5,6}; Line(7)={6,2};
Curve Loop(1)={1,2,3,4}; Curve Loop(2)={5,6,7}; Plane Surface(1)={1,2};
GEO
"$R" mesh "$TMP/touch.geo" -o "$TMP/o9.mesh" -q && "$R" check "$TMP/o9.mesh" >/dev/null &&
  "$R" stats "$TMP/o9.mesh" | grep -q "total 0.905" && ok geo-hole-touching-outer-loop ||
  ko geo-hole-touching-outer-loop
# Listed as a hole of the first, the second is an island with its own ref.
sed 's/Plane Surface(1)={1};/Plane Surface(1)={1,2};/' "$TMP/inside.geo" >"$TMP/island.geo"
"$R" mesh "$TMP/island.geo" -o "$TMP/o8.mesh" -q && "$R" check "$TMP/o8.mesh" >/dev/null &&
  ok geo-island || ko geo-island
# Two squares, only the second in Physical Surface(1), whose tag is the first's id; curve 2 (the
# interface) in no group, Physical Curve(2) holding others: both pairs came out as one ref (QA
# hunt 5 F6). The unnamed ones now take refs above every tag and id.
cat >"$TMP/collide.geo" <<'GEO'
lc = 0.2;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {2, 0, 0, lc};
Point(4) = {2, 1, 0, lc}; Point(5) = {1, 1, 0, lc}; Point(6) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};
Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(1) = {1}; Plane Surface(2) = {2};
Physical Curve(2) = {5, 6, 7};
Physical Surface(1) = {2};
GEO
"$R" mesh "$TMP/collide.geo" -o "$TMP/collide.mesh" -q &&
  /usr/bin/python3 - "$TMP/collide.mesh" <<'PY' && ok geo-unnamed-refs-apart || ko geo-unnamed-refs-apart
import sys
t = open(sys.argv[1]).read().split()
i = t.index('Triangles'); n = int(t[i + 1]); tri = {int(t[i + 2 + 4 * k + 3]) for k in range(n)}
j = t.index('Edges'); m = int(t[j + 1]); edg = {int(t[j + 2 + 3 * k + 2]) for k in range(m)}
sys.exit(0 if tri == {1, 3} and edg == {1, 2, 3, 4, 8} else 1)
PY
exit $fail
