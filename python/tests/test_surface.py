# SPDX-License-Identifier: Apache-2.0
# surface(): `alphapocket surface --json --per-atom`'s numbers, per atom as arrays.
import json

import numpy as np
import pytest

import alphapocket
from conftest import PDB, SMALL, cli


def test_equals_cli():
    out = json.loads(cli("surface", SMALL, "--json", "--per-atom", "-q").stdout)
    s = alphapocket.surface(SMALL)
    assert s.atoms == out["atoms"]
    for key in ("sa_area", "sa_volume", "ms_area", "ms_volume"):
        assert getattr(s, key) == out[key]
    assert isinstance(s.atom_areas, np.ndarray)
    assert s.atom_areas.tolist() == [a["area"] for a in out["per_atom"]]
    assert abs(s.atom_areas.sum() - s.sa_area) <= 1e-9 * s.sa_area
    assert s.atom_volumes.shape == (s.atoms,) and (s.atom_volumes >= 0).all()
    assert abs(s.atom_volumes.sum() - s.sa_volume) <= 1e-9 * s.sa_volume
    assert s.atom_volumes.tolist() == [a["volume"] for a in out["per_atom"]]
    assert s.ms_atom_areas.tolist() == [a["ms_area"] for a in out["per_atom"]]
    assert s.ms_atom_volumes.tolist() == [a["ms_volume"] for a in out["per_atom"]]


def test_ms_per_atom_arrays():
    """Per atom, the MS surface's area and the volume it encloses in the
    atom's power cell: arrays of one value per atom summing to the totals,
    the volume within the SA one; the totals the same without the split."""
    s = alphapocket.surface(SMALL)
    for array in (s.ms_atom_areas, s.ms_atom_volumes):
        assert isinstance(array, np.ndarray) and array.shape == (s.atoms,) and array.dtype == np.float64
    assert abs(s.ms_atom_areas.sum() - s.ms_area) <= 1e-11 * s.ms_area
    assert abs(s.ms_atom_volumes.sum() - s.ms_volume) <= 1e-11 * s.ms_volume
    assert (s.ms_atom_volumes <= s.atom_volumes + 1e-9).all() and (s.ms_atom_volumes > -1e-2).all()
    alone = alphapocket.surface(SMALL, per_atom=False)
    assert alone.ms_atom_areas is None and alone.ms_atom_volumes is None
    assert (alone.ms_area, alone.ms_volume) == (s.ms_area, s.ms_volume)
    assert alphapocket.surface(SMALL, excluded=False).ms_atom_areas is None


def test_ms_per_atom_two_equal_balls():
    """Two equal atoms: the radical plane is their mirror plane, equal shares."""
    s = alphapocket.surface(coordinates=[[0, 0, 0], [3.0, 0, 0]], radii=[1.6, 1.6], probe=1.4)
    assert s.ms_atom_areas[0] == pytest.approx(s.ms_atom_areas[1], rel=1e-12)
    assert s.ms_atom_volumes[0] == pytest.approx(s.ms_atom_volumes[1], rel=1e-12)
    assert s.ms_atom_volumes.sum() == pytest.approx(s.ms_volume, rel=1e-13)


def test_sa_only_and_probe():
    out = json.loads(cli("surface", PDB, "--json", "--sa-only", "--probe", "0", "-q").stdout)
    s = alphapocket.surface(PDB, probe=0, excluded=False)
    assert s.ms_area is None and s.ms_volume is None
    assert (s.sa_area, s.sa_volume) == (out["sa_area"], out["sa_volume"])


def test_one_ball_closed_form():
    s = alphapocket.surface(coordinates=[[1.0, 2.0, 3.0]], radii=[1.5], probe=0.5)
    r = 2.0
    assert abs(s.sa_area - 4 * np.pi * r * r) < 1e-9
    assert abs(s.sa_volume - 4 / 3 * np.pi * r ** 3) < 1e-9
    # The molecular surface of one ball is the ball itself.
    assert abs(s.ms_volume - 4 / 3 * np.pi * 1.5 ** 3) < 1e-9
    assert s.ms_atom_volumes == pytest.approx([4 / 3 * np.pi * 1.5 ** 3], rel=1e-12)
    assert s.ms_atom_areas == pytest.approx([4 * np.pi * 1.5 ** 2], rel=1e-12)


def test_two_balls_per_atom_closed_form():
    """Radii 2 and 1, 2 apart: the power plane at x = 7/4 cuts caps of
    height 1/4 and 3/4; each atom keeps the rest of its ball and sphere."""
    s = alphapocket.surface(coordinates=[[0, 0, 0], [2, 0, 0]], radii=[2.0, 1.0], probe=0, excluded=False)
    cap_volume = lambda h, r: np.pi * h * h * (3 * r - h) / 3
    assert s.atom_volumes == pytest.approx([32 / 3 * np.pi - cap_volume(0.25, 2), 4 / 3 * np.pi - cap_volume(0.75, 1)],
                                           rel=1e-12)
    assert s.atom_areas == pytest.approx([16 * np.pi - 2 * np.pi * 2 * 0.25, 4 * np.pi - 2 * np.pi * 0.75], rel=1e-12)
