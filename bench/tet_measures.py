#!/usr/bin/python3
"""How the remesher's tet measures see a 3D mesh of a benchmark case (issue #7): the harness's
quality (mean ratio in the analytic metric at the centroid, ../shared/bench/evaluate.py) against
the mean ratio in the plain mean of the vertex metrics and in their log-Euclidean mean (the
vertex metrics are the analytic ones, as the harness's .sol gives them): minimum, mean, the
correlation with the harness and the count below 0.5; then the worst tets by the harness.

usage: bench/tet_measures.py CASE MESH [WORST]     e.g. polar1-3d /tmp/p1/pass_8.mesh 10
"""
import os, sys
import numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "bench"))
import evaluate, medit, metrics  # noqa: E402

EDGES = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])


def spectral(M, f):
    w, V = np.linalg.eigh(M)
    return (V * f(w)[..., None, :]) @ np.swapaxes(V, -1, -2)


def quality(M, X):
    d = X[:, EDGES[:, 1]] - X[:, EDGES[:, 0]]
    l2 = np.einsum("nei,nij,nej->n", d, M, d)
    v = np.linalg.det(X[:, 1:] - X[:, :1]) / 6 * np.sqrt(np.linalg.det(M))
    return np.sign(v) * 12 * np.cbrt((3 * np.abs(v)) ** 2) / l2


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    case, mesh = metrics.Case(sys.argv[1]), medit.read_mesh(sys.argv[2])
    worst = int(sys.argv[3]) if len(sys.argv) > 3 else 10
    P, T = mesh["vertices"], mesh["tetrahedra"]
    harness, _ = evaluate.qualities(case, P, T)
    MV = case.tensor(P)
    X = P[T]
    plain = quality(MV[T].mean(axis=1), X)
    log_euclidean = quality(spectral(spectral(MV, np.log)[T].mean(axis=1), np.exp), X)
    print("%d tets; harness: min %.3f mean %.3f, %d below 0.5" % (len(T), harness.min(), harness.mean(),
                                                                 (harness < 0.5).sum()))
    for name, q in (("plain mean", plain), ("log-Euclidean", log_euclidean)):
        print("%-13s min %.3f mean %.3f, correlation with the harness %.3f, %d below 0.5" % (
            name, q.min(), q.mean(), np.corrcoef(q, harness)[0, 1], (q < 0.5).sum()))
    print("worst by the harness: harness / plain / log-Euclidean, centroid")
    for t in np.argsort(harness)[:worst]:
        c = X[t].mean(axis=0)
        print("  %.3f %.3f %.3f  (%.4f, %.4f, %.4f)" % (harness[t], plain[t], log_euclidean[t], *c))


if __name__ == "__main__":
    main()
