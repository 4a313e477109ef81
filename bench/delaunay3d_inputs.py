#!/usr/bin/python3
"""Inputs of bench/delaunay3d_vs_tetgen.sh, written to DIR:
  random_N.node     N uniform random points in the unit cube (seed 1), N in 1e5, 1e6
  grid_50.node      the 51^3 nodes of a regular grid (every cell's 8 corners cospherical)
  cluster.node      200 000 points in 20 clusters of width 1e-4 (seed 2)
  NAME.surf.mesh    the closed surfaces: ../shared/data/surf/*.mesh and the boundary triangles of
                    ../shared/data/vol/*.mesh (vertices and triangles only)
  NAME.surf.node    the vertices of those triangles
Usage: delaunay3d_inputs.py SHARED_DATA DIR"""
import glob
import os
import sys

import meshio
import numpy as np


def write_node(path, p):
    with open(path, "w") as f:
        f.write(f"{len(p)} 3 0 0\n")
        np.savetxt(f, np.column_stack([np.arange(1, len(p) + 1), p]), fmt="%d %.17g %.17g %.17g")


def write_surface(path, points, tris):
    with open(path, "w") as f:
        f.write(f"MeshVersionFormatted 2\nDimension 3\nVertices\n{len(points)}\n")
        np.savetxt(f, np.column_stack([points, np.zeros(len(points))]), fmt="%.17g %.17g %.17g %d")
        f.write(f"Triangles\n{len(tris)}\n")
        np.savetxt(f, np.column_stack([tris + 1, np.zeros(len(tris))]), fmt="%d")
        f.write("End\n")


def main():
    data, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    rng = np.random.default_rng(1)
    for n in (100_000, 1_000_000):
        write_node(f"{out}/random_{n}.node", rng.random((n, 3)))
    g = np.arange(51) / 50.0
    write_node(f"{out}/grid_50.node", np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3))
    rng = np.random.default_rng(2)
    centres = rng.random((20, 3))
    write_node(f"{out}/cluster.node",
               (centres[:, None, :] + 1e-4 * rng.random((20, 10_000, 3))).reshape(-1, 3))
    files = sorted(glob.glob(f"{data}/surf/*.mesh")) + sorted(glob.glob(f"{data}/vol/*.mesh"))
    for path in files:
        m = meshio.read(path)
        tris = np.concatenate([c.data for c in m.cells if c.type == "triangle"])
        used = np.unique(tris)
        renumber = np.full(len(m.points), -1)
        renumber[used] = np.arange(len(used))
        name = os.path.splitext(os.path.basename(path))[0]
        write_surface(f"{out}/{name}.surf.mesh", m.points[used], renumber[tris])
        write_node(f"{out}/{name}.surf.node", m.points[used])


main()
