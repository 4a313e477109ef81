#!/usr/bin/python3
"""Metric fields for the real volumes of ../shared/data/vol (issue #7's real cases).

  real3d_metrics.py iso   MESH -o M.sol   isotropic size D/40 (D = the bounding-box diagonal)
  real3d_metrics.py shell MESH -o M.sol   anisotropic layer along the sphere |x - c| = R (c the
                                          bounding-box centre, R = D/5), like a spherical shock:
                                          across it (radially) h_n = H/20 + (H - H/20) min(1, |d|/w),
                                          along it h_t = H/2 + (H/2) min(1, |d|/w), d = |x - c| - R,
                                          H = D/25, w = D/20 — anisotropy up to 10:1
M = (1/h_n²) n nᵀ + (1/h_t²)(I − n nᵀ), n = (x − c)/|x − c|.  Evaluated analytically at the
mesh's vertices, so that bench/real3d.sh can re-evaluate it on each new mesh (`--box ORIG.mesh`:
c and D from the original mesh, so that the field does not move with the remeshed boundary).
Run with Debian's /usr/bin/python3 (needs python3-numpy).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "bench"))
import medit  # noqa: E402


def iso(P, box):
    lo, hi = box
    h = np.linalg.norm(hi - lo) / 40.0
    return np.tile(np.eye(3) / h**2, (len(P), 1, 1))


def shell(P, box):
    lo, hi = box
    D = np.linalg.norm(hi - lo)
    c, R, H, w = 0.5 * (lo + hi), D / 5.0, D / 25.0, D / 20.0
    x = P - c
    r = np.linalg.norm(x, axis=1)
    n = x / np.maximum(r, 1e-300)[:, None]
    t = np.minimum(1.0, np.abs(r - R) / w)
    hn = H / 20.0 + (H - H / 20.0) * t
    ht = H / 2.0 + (H / 2.0) * t
    nn = np.einsum("ni,nj->nij", n, n)
    return nn / hn[:, None, None] ** 2 + (np.eye(3) - nn) / ht[:, None, None] ** 2


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("field", choices=["iso", "shell"])
    ap.add_argument("mesh")
    ap.add_argument("-o", required=True)
    ap.add_argument("--box", help="take c and D from this mesh (the original), not from MESH")
    a = ap.parse_args()
    P = medit.read_mesh(a.mesh)["vertices"]
    B = medit.read_mesh(a.box)["vertices"] if a.box else P
    box = (B.min(axis=0), B.max(axis=0))
    medit.write_metric_sol(a.o, iso(P, box) if a.field == "iso" else shell(P, box))


if __name__ == "__main__":
    main()
