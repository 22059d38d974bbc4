#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The persistence of a point cloud: points on a torus, whose two 1-cycles
and one 2-cycle stand out of the noise in the alpha complex's diagram.

Usage: point_cloud_persistence.py [POINTS]   (POINTS: x y z per line; default: 2000 points on a torus)
"""
import sys

import numpy as np

import alphapocket


def torus(n=2000, big=3.0, small=1.0, seed=7):
    rng = np.random.default_rng(seed)
    u, v = rng.uniform(0, 2 * np.pi, n), rng.uniform(0, 2 * np.pi, n)
    return np.c_[(big + small * np.cos(v)) * np.cos(u), (big + small * np.cos(v)) * np.sin(u), small * np.sin(v)]


def main(points):
    complex_ = alphapocket.AlphaComplex(points)
    pairs = complex_.persistence()  # rows: dimension, birth alpha_sq, death alpha_sq (inf: never)
    print(f"{len(points)} points, {len(complex_.spectrum)} critical values, {len(pairs)} persistence pairs")
    for dim in range(3):
        rows = pairs[pairs[:, 0] == dim]
        longest = rows[np.argsort(rows[:, 1] - rows[:, 2])][:3]  # longest first
        print(f"dimension {dim}: " + ", ".join(f"[{b:.3g}, {d:.3g})" for _, b, d in longest))
    # Where the torus is a torus: one component, two 1-cycles, one void.
    # Betti number k at a = pairs of dimension k born at or before a that
    # die after it, at once for every a halfway between two critical values
    # (a critical value itself is the nearest double to an exact value, on
    # either side of it).
    spectrum = complex_.spectrum
    values = (spectrum[:-1] + spectrum[1:]) / 2
    betti = np.array([np.searchsorted(np.sort(pairs[pairs[:, 0] == k, 1]), values, side="right") -
                      np.searchsorted(np.sort(pairs[pairs[:, 0] == k, 2]), values, side="right") for k in range(3)])
    torus_like = np.flatnonzero((betti.T == [1, 2, 1]).all(axis=1))
    if len(torus_like) == 0:
        print("no alpha_sq with Betti numbers 1 2 1")
        return
    alpha_sq = values[torus_like[0]]
    assert complex_.betti(alpha_sq) == [1, 2, 1]
    vertices, faces = complex_.shape_mesh(alpha_sq)
    print(f"Betti numbers 1 2 1 from alpha_sq {alpha_sq:.4g}: {len(faces)} boundary triangles")

if __name__ == "__main__":
    main(np.loadtxt(sys.argv[1], ndmin=2) if len(sys.argv) > 1 else torus())
