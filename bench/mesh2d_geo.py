#!/usr/bin/python3
"""Writes a Gmsh .geo for the boundary of a planar DOMAIN.mesh (Edges only), for
bench/mesh2d_vs_gmsh.sh: one Point per boundary vertex, one Line per edge, the loops chained from
the edges, the loop of largest area as the outer boundary and the others as holes.

  mesh2d_geo.py DOMAIN.mesh OUT.geo keep     each edge stays one segment (Transfinite Curve = 2),
                                             size at a point = mean length of its edges
  mesh2d_geo.py DOMAIN.mesh OUT.geo H        uniform size H (the edges are split at H)
"""
import math
import sys

import meshio


def main():
    src, out, mode = sys.argv[1:4]
    m = meshio.read(src)
    xy = m.points[:, :2]
    edges = [tuple(e) for c in m.cells if c.type == "line" for e in c.data]
    length = {}
    for a, b in edges:
        l = math.dist(xy[a], xy[b])
        for v in (a, b):
            length.setdefault(v, []).append(l)
    nxt = {a: b for a, b in edges}
    loops, seen = [], set()
    for a, _ in edges:
        if a in seen:
            continue
        loop, v = [], a
        while v not in seen:
            seen.add(v)
            loop.append(v)
            v = nxt[v]
        loops.append(loop)
    area = lambda l: 0.5 * abs(sum(xy[l[i]][0] * xy[l[(i + 1) % len(l)]][1] - xy[l[(i + 1) % len(l)]][0] * xy[l[i]][1] for i in range(len(l))))
    loops.sort(key=area, reverse=True)
    with open(out, "w") as f:
        for v, ls in sorted(length.items()):
            h = sum(ls) / len(ls) if mode == "keep" else float(mode)
            f.write(f"Point({v + 1}) = {{{xy[v][0]!r}, {xy[v][1]!r}, 0, {h!r}}};\n")
        line = 0
        for k, loop in enumerate(loops):
            ids = []
            for i, a in enumerate(loop):
                line += 1
                f.write(f"Line({line}) = {{{a + 1}, {loop[(i + 1) % len(loop)] + 1}}};\n")
                if mode == "keep":
                    f.write(f"Transfinite Curve{{{line}}} = 2;\n")
                ids.append(line)
            f.write(f"Curve Loop({k + 1}) = {{{', '.join(map(str, ids))}}};\n")
        f.write(f"Plane Surface(1) = {{{', '.join(str(k + 1) for k in range(len(loops)))}}};\n")
        f.write("Physical Surface(1) = {1};\n")


main()
