# SPDX-License-Identifier: Apache-2.0
"""alphapocket.track: frames from an MDAnalysis Universe and from arrays
give the same tracks as the command line's models of the same file."""
import gzip
import os
import subprocess
import warnings

import numpy as np
import pytest

import alphapocket

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data")


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    """1l2y's models 1-4 as a multi-model PDB file."""
    path = tmp_path_factory.mktemp("track") / "m4.pdb"
    with gzip.open(os.path.join(DATA, "1l2y.pdb.gz"), "rt") as f:
        lines = []
        for line in f:
            if line.startswith("MODEL") and int(line.split()[1]) == 5:
                break
            if line.startswith(("MODEL", "ATOM", "TER", "ENDMDL")):
                lines.append(line)
    path.write_text("".join(lines) + "END\n")
    return path


def first_model(path, out):
    text = path.read_text()
    out.write_text(text[:text.index("ENDMDL")] + "END\n")
    return out


def test_arrays_equal_the_models(models, tmp_path):
    import gemmi
    st = gemmi.read_structure(str(models))
    xyz = np.array([[a.pos.tolist() for res in m[0] for a in res] for m in st])
    topology = first_model(models, tmp_path / "m1.pdb")
    result = alphapocket.track(xyz, topology=topology, times=[0, 10, 20, 30], tunnels_from="none")
    assert len({r["frame"] for r in result.frames}) == 4
    assert [r["time"] for r in result.frames if r["rank"] == 1 and r["kind"] == "pocket"] == [0, 10, 20, 30]
    assert result.frequency.shape == result.density.shape and result.frequency.ndim == 3
    assert 0 <= result.frequency.min() and result.frequency.max() <= 1
    assert result.tracks and all(t["frames"] >= 1 for t in result.tracks)
    exe = os.environ.get("ALPHAPOCKET_EXE")
    if exe:
        subprocess.run([exe, "track", str(models), "--tunnels-from", "none", "-o", str(tmp_path / "cli")], check=True,
                       capture_output=True)
        with open(tmp_path / "cli" / "tracks.csv") as f:
            assert f.read() == dict(result._core.files())["tracks.csv"]
    written = result.write(tmp_path / "out")
    assert "frequency.dx" in written and (tmp_path / "out" / "tracks.csv").exists()


def test_universe(models, tmp_path):
    mda = pytest.importorskip("MDAnalysis")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        u = mda.Universe(str(models))
    result = alphapocket.track(u, stride=2, tunnels_from="none")
    assert sorted({r["frame"] for r in result.frames}) == [0, 1]
    topology = first_model(models, tmp_path / "m1.pdb")
    xyz = np.array([u.atoms.positions.copy() for ts in u.trajectory[::2]])
    direct = alphapocket.track(xyz, topology=topology, tunnels_from="none")
    # The same pockets (MDAnalysis's PDB keeps 3 decimals, as the file).
    assert [t["frames"] for t in result.tracks] == [t["frames"] for t in direct.tracks]
    np.testing.assert_allclose([t["mean_sa_volume"] or 0 for t in result.tracks],
                               [t["mean_sa_volume"] or 0 for t in direct.tracks], atol=1e-3)


def test_bad_arrays(models, tmp_path):
    topology = first_model(models, tmp_path / "m1.pdb")
    with pytest.raises(alphapocket.BadInputError, match="300 atoms, but the topology has 304"):
        alphapocket.track(np.zeros((2, 300, 3)), topology=topology)
    with pytest.raises(alphapocket.MisuseError, match="topology"):
        alphapocket.track(np.zeros((2, 304, 3)))
    with pytest.raises(alphapocket.MisuseError, match="unknown option"):
        alphapocket.track(np.zeros((2, 304, 3)), topology=topology, colour="red")
