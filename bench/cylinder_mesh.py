#!/usr/bin/python3
"""The faceted cylinder of issue #7's curved-boundary case, and its metric.

  cylinder_mesh.py MESH SOL [HN]
  cylinder_mesh.py --side OUT.mesh      prints the side vertices (in a triangle of ref 1) of a
                                        remeshed cylinder: their count and largest |radius - 1|

MESH: the cylinder r = 1, z in [0, 1], 24 flat facets, 2 layers of prisms (3 tets each), refs side 1,
bottom 2, top 3. SOL: a metric of size 0.3 along the circle and the axis, 0.3 -> HN radially from the
axis to the side (default 0.03, 10x; 0.003 is the issue's 100x).
"""
import math
import sys


def side(path):
    toks = open(path).read().split()
    i = toks.index('Vertices')
    n = int(toks[i + 1])
    xyz = [tuple(map(float, toks[i + 2 + 4 * k: i + 5 + 4 * k])) for k in range(n)]
    i = toks.index('Triangles')
    nt = int(toks[i + 1])
    on_side = set()
    for k in range(nt):
        a, b, c, r = map(int, toks[i + 2 + 4 * k: i + 6 + 4 * k])
        if r == 1:
            on_side |= {a - 1, b - 1, c - 1}
    print(len(on_side), max(abs(math.hypot(xyz[v][0], xyz[v][1]) - 1) for v in on_side))


def main():
    if len(sys.argv) == 3 and sys.argv[1] == '--side':
        return side(sys.argv[2])
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    mesh, sol = sys.argv[1], sys.argv[2]
    hn = float(sys.argv[3]) if len(sys.argv) == 4 else 0.03
    F, L = 24, 2
    ring = F + 1
    pts, tets, tris = [], [], []
    for k in range(L + 1):
        z = k / L
        pts.append((0.0, 0.0, z))
        pts += [(math.cos(2 * math.pi * i / F), math.sin(2 * math.pi * i / F), z) for i in range(F)]

    def vid(k, i):
        return k * ring + i

    def vol(t):
        a, b, c, d = (pts[v] for v in t)
        u = [b[j] - a[j] for j in range(3)]
        v = [c[j] - a[j] for j in range(3)]
        w = [d[j] - a[j] for j in range(3)]
        return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                + u[2] * (v[0] * w[1] - v[1] * w[0]))

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
    with open(mesh, 'w') as f:
        f.write('MeshVersionFormatted 2\nDimension 3\nVertices\n%d\n' % len(pts))
        f.writelines('%.17g %.17g %.17g 0\n' % p for p in pts)
        f.write('Triangles\n%d\n' % len(tris))
        f.writelines('%d %d %d %d\n' % (a + 1, b + 1, c + 1, r) for a, b, c, r in tris)
        f.write('Tetrahedra\n%d\n' % len(tets))
        f.writelines('%d %d %d %d 1\n' % tuple(v + 1 for v in t) for t in tets)
        f.write('End\n')
    h = 0.3
    with open(sol, 'w') as f:
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
            f.write('%.17g %.17g %.17g %.17g %.17g %.17g\n'
                    % (m[0][0], m[0][1], m[1][1], m[0][2], m[1][2], m[2][2]))
        f.write('End\n')


if __name__ == '__main__':
    main()
