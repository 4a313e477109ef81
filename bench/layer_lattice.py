#!/usr/bin/python3
"""What a structured mesh of polar1-3d's layer gets by the harness's measures (issue #7): a BCC
lattice (grid points and cell centres, four tets on each face between two cells) laid out in
(tangential, radial, axial) metric units, the radial unit coordinate v mapped to the radius by the
case's size h_r = h0 + 2 (0.1 - h0) |r - 0.5| (r - 0.5 = h0 (exp(k |v|) - 1) / k, k = 2 (0.1 - h0)),
the tangential one to the angle on the radius 0.5; quality (analytic metric at the centroid) and
edge lengths (integrated, evaluate.py) of the tets within |r - 0.5| < 0.006, for lattice spacings
(tangential, radial, axial) in metric units. Prints the best spacings by q min, among those whose
shortest edge is at least 0.5.

usage: bench/layer_lattice.py [CASE]        (default polar1-3d; its h0 and s are used)
"""
import itertools
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "bench"))
import evaluate, metrics, topo  # noqa: E402


def lattice(case, st, sr, sz, nt=8, nv=6, nz=4):
    """The BCC lattice's points (physical) and tets, spacings st, sr, sz in metric units."""
    ids = {}

    def pid(key):
        return ids.setdefault(key, len(ids))

    tets = []
    for i, j, l in itertools.product(range(-nt, nt), range(-nv, nv), range(-nz, nz)):
        for d in range(3):
            o = [0, 0, 0]
            o[d] = 1
            c1, c2 = ("c", i, j, l), ("c", i + o[0], j + o[1], l + o[2])
            a, b = [x for x in range(3) if x != d]
            base = [i, j, l]
            base[d] += 1
            square = []
            for da, db in ((0, 0), (1, 0), (1, 1), (0, 1)):
                g = list(base)
                g[a] += da
                g[b] += db
                square.append(("g", *g))
            for e in range(4):
                tets.append([pid(c1), pid(c2), pid(square[e]), pid(square[(e + 1) % 4])])
    X = np.zeros((len(ids), 3))
    for key, n in ids.items():
        off = 0.5 if key[0] == "c" else 0.0
        X[n] = [key[1] + off, key[2] + off, key[3] + off]
    h0, hm = case.s * case.h0, case.s * case.hmax
    k = 2 * (case.hmax - case.h0)
    v = X[:, 1] * sr
    r = 0.5 + np.sign(v) * h0 * (np.exp(k * np.abs(v)) - 1) / k
    theta = X[:, 0] * st * hm / 0.5
    P = np.column_stack([r * np.cos(theta), r * np.sin(theta), 0.5 + X[:, 2] * sz * hm])
    T = np.array(tets)
    flip = np.linalg.det(P[T[:, 1:]] - P[T[:, :1]]) < 0
    T[flip] = T[flip][:, [0, 2, 1, 3]]
    return P, T


def main():
    case = metrics.Case(sys.argv[1] if len(sys.argv) > 1 else "polar1-3d")
    rows = []
    for st, sr, sz in itertools.product((0.35, 0.4, 0.43, 0.46, 0.5, 0.6), (1.0, 1.1, 1.2, 1.3),
                                        (0.8, 0.9, 1.0)):
        P, T = lattice(case, st, sr, sz)
        q, _ = evaluate.qualities(case, P, T)
        C = P[T].mean(axis=1)
        inner = np.abs(np.hypot(C[:, 0], C[:, 1]) - 0.5) < 0.006
        E = np.unique(np.sort(T[inner][:, topo.TET_EDGES].reshape(-1, 2), axis=1), axis=0)
        L = evaluate.edge_lengths(case, P, E)
        rows.append((q[inner].min(), q[inner].mean(), L.min(), L.max(), evaluate.in_range(L).mean(),
                     st, sr, sz))
    rows.sort(reverse=True)
    print("spacing t/r/z   q min  q mean  lengths      in band")
    for qmin, qmean, lmin, lmax, inb, st, sr, sz in [r for r in rows if r[2] >= 0.5][:10]:
        print("%.2f/%.1f/%.1f   %.3f  %.3f   %.3f-%.3f  %.1f%%" % (st, sr, sz, qmin, qmean, lmin, lmax, 100 * inb))


if __name__ == "__main__":
    main()
