#!/usr/bin/python3
"""Writes a constant metric .sol for every vertex of a 2D .mesh: sizes H1, H2 along directions
turned by DEG degrees (for bench/mesh2d_aniso.sh).
  bench/const_metric.py MESH OUT.sol H1 H2 DEG"""
import math
import sys

import meshio
import numpy as np

mesh, out, h1, h2, deg = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:6])
n = len(meshio.read(mesh).points)
c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
rot = np.array([[c, -s], [s, c]])
m = rot @ np.diag([1 / h1**2, 1 / h2**2]) @ rot.T
with open(out, "w") as f:
    f.write("MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n%d\n1 3\n" % n)
    f.write(("%.17g %.17g %.17g\n" % (m[0, 0], m[0, 1], m[1, 1])) * n)
    f.write("End\n")
