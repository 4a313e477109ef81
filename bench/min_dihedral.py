#!/usr/bin/python3
"""Prints the minimum dihedral angle (degrees) and the tetrahedron count of a .mesh/.node+.ele
volume mesh: bench/min_dihedral.py VOL.mesh   or   bench/min_dihedral.py BASE (TetGen BASE.node/.ele)."""
import sys

import numpy as np


def read_medit(path):
    pts, tets = [], []
    with open(path) as f:
        tok = f.read().split()
    i = 0
    while i < len(tok):
        w = tok[i]
        if w == "Vertices":
            n = int(tok[i + 1]); i += 2
            pts = np.array(tok[i:i + 4 * n], dtype=float).reshape(n, 4)[:, :3]; i += 4 * n
        elif w == "Tetrahedra":
            n = int(tok[i + 1]); i += 2
            tets = np.array(tok[i:i + 5 * n], dtype=np.int64).reshape(n, 5)[:, :4] - 1; i += 5 * n
        else:
            i += 1
    return pts, tets


def read_tetgen(base):
    with open(base + ".node") as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
    n = int(lines[0][0])
    ids = np.array([int(l[0]) for l in lines[1:n + 1]])
    pts = np.array([[float(x) for x in l[1:4]] for l in lines[1:n + 1]])
    with open(base + ".ele") as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
    m = int(lines[0][0])
    tets = np.array([[int(x) for x in l[1:5]] for l in lines[1:m + 1]]) - ids.min()
    return pts, tets


def min_dihedral(pts, tets):
    p = pts[tets]  # (m, 4, 3)
    best = 180.0
    pairs = [(0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1)]
    for a, b, c, d in pairs:  # edge ab, faces abc and abd
        e = p[:, b] - p[:, a]
        n1 = np.cross(e, p[:, c] - p[:, a])
        n2 = np.cross(e, p[:, d] - p[:, a])
        cos = np.einsum("ij,ij->i", n1, n2) / (np.linalg.norm(n1, axis=1) * np.linalg.norm(n2, axis=1))
        best = min(best, float(np.degrees(np.arccos(np.clip(cos, -1, 1))).min()))
    return best


arg = sys.argv[1]
pts, tets = read_medit(arg) if arg.endswith(".mesh") else read_tetgen(arg)
print(f"{min_dihedral(pts, tets):.3g} {len(tets)}")
