#!/usr/bin/python3
"""Metrics for bench/curved_interfaces3d.sh, one tensor per vertex of a Medit MESH:

  curved_interfaces3d_metrics.py MESH OUT.sol cyl R HN HT W    radial size HN within W of the
                                                               cylinder r = R about z, HT elsewhere
  curved_interfaces3d_metrics.py MESH OUT.sol shell R H0 HT W  isotropic H0 within W of the sphere
                                                               of radius R at the origin, HT elsewhere
  curved_interfaces3d_metrics.py MESH OUT.sol rot H1 H2 H3 DX DY DZ   constant: H3 along (DX, DY, DZ)

Sizes grow linearly from the layer (3 W to reach HT), as QA hunt 4's scripts made them.
"""
import sys

import numpy as np


def points(path):
    toks = open(path).read().split()
    i = toks.index('Vertices')
    n = int(toks[i + 1])
    return np.array(toks[i + 2:i + 2 + 4 * n], float).reshape(n, 4)[:, :3]


def main():
    mesh, out, kind, *a = sys.argv[1:]
    a = [float(x) for x in a]
    p = points(mesh)
    n = len(p)
    m = np.zeros((n, 3, 3))
    if kind == 'cyl':
        r0, hn, ht, w = a
        rr = np.hypot(p[:, 0], p[:, 1])
        d = np.abs(rr - r0)
        h = np.where(d < w, hn, np.minimum(ht, hn * (1 + 3 * (d - w) / w)))
        u = np.stack([p[:, 0], p[:, 1], 0 * rr], 1) / np.maximum(rr, 1e-12)[:, None]
        m[:] = np.eye(3) / ht**2
        m += np.einsum('ni,nj->nij', u, u) * (1 / h**2 - 1 / ht**2)[:, None, None]
    elif kind == 'shell':
        r0, h0, ht, w = a
        d = np.abs(np.linalg.norm(p, axis=1) - r0)
        h = np.where(d < w, h0, np.minimum(ht, h0 * (1 + 3 * (d - w) / w)))
        m[:] = np.eye(3)[None] / (h**2)[:, None, None]
    elif kind == 'rot':
        dv = np.array(a[3:6]) / np.linalg.norm(a[3:6])
        t = np.cross(dv, [1, 0, 0]) if abs(dv[0]) < 0.9 else np.cross(dv, [0, 1, 0])
        t /= np.linalg.norm(t)
        s = np.cross(dv, t)
        m[:] = np.outer(t, t) / a[0]**2 + np.outer(s, s) / a[1]**2 + np.outer(dv, dv) / a[2]**2
    else:
        sys.exit('kind: cyl, shell or rot')
    with open(out, 'w') as f:
        f.write('MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n%d\n1 3\n' % n)
        for q in m:
            f.write('%.17g %.17g %.17g %.17g %.17g %.17g\n'
                    % (q[0, 0], q[0, 1], q[1, 1], q[0, 2], q[1, 2], q[2, 2]))
        f.write('End\n')


main()
