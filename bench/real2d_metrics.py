#!/usr/bin/python3
"""Metric fields for the real 2D domains of ../shared/data/2d (issue #4's real cases).

  real2d_metrics.py lake MESH -o M.sol     shore-refined isotropic field on the lake of Geneva:
                                           h = hmin + (hmax - hmin) min(1, d / D), d = distance to
                                           the shore (all boundary edges), hmin 0.05, hmax 1, D 8
  real2d_metrics.py wake MESH -o M.sol     NACA 0012 in a circle: isotropic refinement at the
                                           airfoil (h = 0.004 + 0.5 min(1, d / 2)) intersected with
                                           a wake-aligned anisotropic metric in the wake behind the
                                           trailing edge, |y| < 0.05 + 0.1 (x - 1): along x
                                           0.02 + 0.05 (x - 1), across 0.002 + 0.05 |y| / half-width
Distances are to the mesh's boundary edges (brute force with numpy, fine for these sizes).
Run with Debian's /usr/bin/python3 (needs python3-numpy).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "bench"))
import medit  # noqa: E402


def segment_distance(P, A, B):
    """Distance from each point of P (n,2) to the nearest segment [A_k, B_k]."""
    best = np.full(len(P), np.inf)
    for a, b in zip(A, B):
        ab = b - a
        t = np.clip(((P - a) @ ab) / (ab @ ab), 0.0, 1.0)
        best = np.minimum(best, np.linalg.norm(P - (a + t[:, None] * ab), axis=1))
    return best


def iso(h):
    M = np.zeros((len(h), 2, 2))
    M[:, 0, 0] = M[:, 1, 1] = 1.0 / h**2
    return M


def intersect(M1, M2):
    """Intersection by simultaneous reduction, point by point."""
    out = np.empty_like(M1)
    for i, (a, b) in enumerate(zip(M1, M2)):
        w, V = np.linalg.eigh(a)
        r = V @ np.diag(w**-0.5) @ V.T           # a^(-1/2)
        mu, Q = np.linalg.eigh(r @ b @ r)
        P = V @ np.diag(w**0.5) @ V.T @ Q        # a^(1/2) Q
        out[i] = P @ np.diag(np.maximum(1.0, mu)) @ P.T
    return out


def lake(mesh):
    P, E = mesh["vertices"][:, :2], mesh["edges"]
    d = segment_distance(P, P[E[:, 0]], P[E[:, 1]])
    return iso(0.05 + (1.0 - 0.05) * np.minimum(1.0, d / 8.0))


def wake(mesh):
    P, E, refs = mesh["vertices"][:, :2], mesh["edges"], mesh["edges_refs"]
    airfoil = E[refs == 99]
    d = segment_distance(P, P[airfoil[:, 0]], P[airfoil[:, 1]])
    M = iso(0.004 + 0.5 * np.minimum(1.0, d / 2.0))
    x, y = P[:, 0], P[:, 1]
    spread = 0.05 + 0.1 * np.maximum(x - 1.0, 0.0)    # wake half-width, widening downstream
    wake_zone = (x > 1.0) & (np.abs(y) < spread)
    hx = 0.02 + 0.05 * np.maximum(x - 1.0, 0.0)        # along the wake
    hy = 0.002 + 0.05 * np.abs(y) / spread              # across: fine on the centre line
    W = np.zeros_like(M)
    W[:, 0, 0], W[:, 1, 1] = 1.0 / hx**2, 1.0 / hy**2
    behind = wake_zone
    M[behind] = intersect(M[behind], W[behind])
    return M


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("field", choices=["lake", "wake"])
    ap.add_argument("mesh")
    ap.add_argument("-o", required=True)
    a = ap.parse_args()
    mesh = medit.read_mesh(a.mesh)
    medit.write_metric_sol(a.o, lake(mesh) if a.field == "lake" else wake(mesh))


if __name__ == "__main__":
    main()
