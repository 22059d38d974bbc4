# SPDX-License-Identifier: Apache-2.0
# AlphaComplex: spectrum, classification, Betti numbers, persistence and
# shape against closed forms and the CLI.
import math

import numpy as np

import alphapocket
from conftest import DATA, cli


def torus(n=1500, R=3.0, r=1.0, seed=3):
    rng = np.random.default_rng(seed)
    u, v = rng.uniform(0, 2 * np.pi, n), rng.uniform(0, 2 * np.pi, n)
    return np.c_[(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)]


def test_regular_tetrahedron():
    p = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float)
    ac = alphapocket.AlphaComplex(p)
    # Edge 2*sqrt2: half squared = 2; triangle circumradius^2 = 8/3; cell 3.
    assert np.allclose(ac.spectrum, [0.0, 2.0, 8 / 3, 3.0])
    counts = ac.classify(2.5)  # rows: dimension, columns: exterior, singular, regular, interior
    assert counts[1].tolist() == [0, 6, 0, 0] and counts[2].tolist() == [4, 0, 0, 0]  # edges alone: singular
    assert ac.classify(3.0)[2].tolist() == [0, 0, 4, 0] and ac.classify(3.0)[3].tolist() == [0, 0, 0, 1]
    assert ac.betti(2.5) == [1, 3, 0]
    assert ac.betti(2.9) == [1, 0, 1]
    assert ac.betti(3.0) == [1, 0, 0]
    v, f = ac.shape_mesh(3.0)
    assert v.shape == (4, 3) and f.shape == (4, 3)


def test_torus_persistence():
    ac = alphapocket.AlphaComplex(torus())
    pairs = ac.persistence()
    assert pairs.shape[1] == 3
    # One infinite component; the two longest 1-cycles are the torus's.
    assert ((pairs[:, 0] == 0) & np.isinf(pairs[:, 2])).sum() == 1
    ones = pairs[pairs[:, 0] == 1]
    lengths = np.sort(ones[:, 2] - ones[:, 1])[::-1]
    assert lengths[1] > 3 * lengths[2]


def test_persistence_equals_cli():
    out = cli("persistence", DATA / "cube_grid.xyz", "-q").stdout.split("\n")
    rows = [line.split() for line in out if line]
    ac = alphapocket.AlphaComplex(np.loadtxt(DATA / "cube_grid.xyz"))
    pairs = ac.persistence()
    assert len(rows) == len(pairs)
    for (d, b, e), row in zip(pairs, rows):
        assert int(row[0]) == d and float(row[1]) == b and float(row[2]) == e


def test_weighted_vertex_values():
    p = np.array([[0, 0, 0], [4, 0, 0], [0, 4, 0], [0, 0, 4]], dtype=float)
    ac = alphapocket.AlphaComplex(p, weights=[1.0, 4.0, 0.0, 0.0])
    assert ac.spectrum[0] == -4.0 and -1.0 in ac.spectrum
    assert len(ac) == 4


def test_threads_same_complex():
    # 2^15 points or more are triangulated, and their complex built, on the threads: the same
    # spectrum, counts, Betti numbers, diagram and shape (faces in another order).
    p = np.random.default_rng(5).uniform(0, 1, (40000, 3))
    one, two = alphapocket.AlphaComplex(p), alphapocket.AlphaComplex(p, threads=2)
    assert np.array_equal(one.spectrum, two.spectrum)
    assert np.array_equal(one.persistence(), two.persistence())
    alpha_sq = float(one.spectrum[len(one.spectrum) // 3])
    assert np.array_equal(one.classify(alpha_sq), two.classify(alpha_sq))
    assert one.betti(alpha_sq) == two.betti(alpha_sq)
    faces = [np.sort(np.sort(ac.shape_mesh(alpha_sq)[1], axis=1), axis=0) for ac in (one, two)]
    assert len(faces[0]) > 1000 and np.array_equal(faces[0], faces[1])
