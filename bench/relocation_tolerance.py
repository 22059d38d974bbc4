#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# First-order tolerances of the facets of the Delaunay triangulation of n random points:
# delta_f = |D| / sum_i ||grad_i D|| (D the insphere determinant of the facet's 5 points),
# a first-order estimate of the tolerance filtering relocations certifies; per vertex the min
# over the facets whose 5 points hold it. Prints the share of vertices and of facets that
# a move of every point by s NN leaves within tolerance.
# Usage: bench/relocation_tolerance.py [N] (default 1e5; 1e4 takes seconds). Needs python3-scipy.
import sys, numpy as np
from scipy.spatial import Delaunay, cKDTree
n = int(float(sys.argv[1])) if len(sys.argv) > 1 else 100000
rng = np.random.default_rng(1)
P = rng.random((n, 3))
nn = cKDTree(P).query(P, k=2)[0][:, 1].mean()
T = Delaunay(P)
S, N = T.simplices, T.neighbors
# each interior facet once: cell c, neighbour m = N[c,k] > c
c, k = np.nonzero(N >= 0)
m = N[c, k]
keep = m > c
c, k, m = c[keep], k[keep], m[keep]
# the far vertex of m: the one not in S[c]
Sm = S[m]
inC = (Sm[:, :, None] == S[c][:, None, :]).any(axis=2)
far = Sm[np.arange(len(m)), np.argmin(inC, axis=1)]
pts = np.concatenate([S[c], far[:, None]], axis=1)  # 5 vertex ids
X = P[pts]  # (F,5,3)
def det(X):
    q = X[:, :4, :] - X[:, 4:5, :]
    h = (q * q).sum(axis=2)
    M = np.concatenate([q, h[:, :, None]], axis=2)
    return np.linalg.det(M)
D = det(X)
g = np.zeros(len(D))
h = 1e-7
for i in range(5):
    gi = np.zeros(len(D))
    for a in range(3):
        Y = X.copy(); Y[:, i, a] += h
        gi += ((det(Y) - D) / h) ** 2
    g += np.sqrt(gi)
delta = np.abs(D) / g / nn  # in NN
tol = np.full(n, np.inf)
np.minimum.at(tol, pts.ravel(), np.repeat(delta, 5))
for s in (0.01, 0.02, 0.05, 0.1, 0.2):
    safe_v = (tol > s).mean()
    safe_f = (delta > s).mean()
    # facets whose 5 vertices are all safe (vertex tolerances)
    skip_f = (tol[pts] > s).all(axis=1).mean()
    print(f"move {s:5.2f} NN: vertices within tolerance {100*safe_v:5.1f} %, facets with delta > move {100*safe_f:5.1f} %, facets skipped (all 5 safe) {100*skip_f:5.1f} %")
print("facet tolerance quantiles (NN):", np.quantile(delta, [0.01, 0.05, 0.1, 0.25, 0.5]).round(4))
print("vertex tolerance quantiles (NN):", np.quantile(tol, [0.1, 0.25, 0.5, 0.75, 0.9]).round(4))
