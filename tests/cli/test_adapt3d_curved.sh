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
/usr/bin/python3 - "$TMP/cyl.mesh" "$TMP/cyl.sol" <<'PY'
import math, sys
F, L = 24, 2
ring = F + 1
pts, tets, tris = [], [], []
for k in range(L + 1):
    z = k / L
    pts.append((0.0, 0.0, z))
    pts += [(math.cos(2 * math.pi * i / F), math.sin(2 * math.pi * i / F), z) for i in range(F)]
vid = lambda k, i: k * ring + i
def vol(t):
    a, b, c, d = (pts[v] for v in t)
    u = [b[j] - a[j] for j in range(3)]; v = [c[j] - a[j] for j in range(3)]; w = [d[j] - a[j] for j in range(3)]
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])
for k in range(L):
    for i in range(F):
        t = sorted([0, 1 + i, 1 + (i + 1) % F])
        a, b, c = (vid(k, x) for x in t)
        a1, b1, c1 = (vid(k + 1, x) for x in t)
        for tet in ([a, b, c, c1], [a, b, b1, c1], [a, a1, b1, c1]):
            if vol(tet) < 0:
                tet[2], tet[3] = tet[3], tet[2]
            tets.append(tet)
        tris += [(b, c, c1, 1), (b, c1, b1, 1)]
for i in range(F):
    j = 1 + (i + 1) % F
    tris += [(vid(0, 0), vid(0, j), vid(0, 1 + i), 2), (vid(L, 0), vid(L, 1 + i), vid(L, j), 3)]
with open(sys.argv[1], 'w') as f:
    f.write('MeshVersionFormatted 2\nDimension 3\nVertices\n%d\n' % len(pts))
    f.writelines('%.17g %.17g %.17g 0\n' % p for p in pts)
    f.write('Triangles\n%d\n' % len(tris))
    f.writelines('%d %d %d %d\n' % (a + 1, b + 1, c + 1, r) for a, b, c, r in tris)
    f.write('Tetrahedra\n%d\n' % len(tets))
    f.writelines('%d %d %d %d 1\n' % tuple(v + 1 for v in t) for t in tets)
    f.write('End\n')
h, hn = 0.3, 0.03
with open(sys.argv[2], 'w') as f:
    f.write('MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n%d\n1 3\n' % len(pts))
    for x, y, z in pts:
        rho = math.hypot(x, y)
        m = [[1 / h ** 2 if i == j else 0.0 for j in range(3)] for i in range(3)]
        if rho > 0:
            s = h - (h - hn) * min(rho, 1.0)
            e = (x / rho, y / rho, 0.0)
            for i in range(3):
                for j in range(3):
                    m[i][j] += (1 / s ** 2 - 1 / h ** 2) * e[i] * e[j]
        f.write('%.17g %.17g %.17g %.17g %.17g %.17g\n' % (m[0][0], m[0][1], m[1][1], m[0][2], m[1][2], m[2][2]))
    f.write('End\n')
PY

# Side vertices (in a triangle of ref 1): count and largest |radius - 1|.
side() {
  /usr/bin/python3 - "$1" <<'PY'
import math, sys
toks = open(sys.argv[1]).read().split()
i = toks.index('Vertices'); n = int(toks[i + 1])
xyz = [tuple(map(float, toks[i + 2 + 4 * k: i + 5 + 4 * k])) for k in range(n)]
i = toks.index('Triangles'); nt = int(toks[i + 1])
side = set()
for k in range(nt):
    a, b, c, r = map(int, toks[i + 2 + 4 * k: i + 6 + 4 * k])
    if r == 1:
        side |= {a - 1, b - 1, c - 1}
print(len(side), max(abs(math.hypot(xyz[v][0], xyz[v][1]) - 1) for v in side))
PY
}
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
/usr/bin/python3 -c "import sys; sys.exit(0 if $n > 200 and $err < 1e-3 else 1)" &&
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
