# SPDX-License-Identifier: Apache-2.0
"""alphapocket.track: frames given as arrays or as an MDAnalysis Universe
give the files `alphapocket track` writes for the same frames."""
import csv
import gzip
import io
import warnings

import numpy as np
import pytest

import alphapocket
from conftest import DATA, cli

COMPARED = ("frames.csv", "tracks.csv", "events.csv", "frequency.dx", "density.dx")


@pytest.fixture(scope="module")
def ensemble(tmp_path_factory):
    """1l2y's models 1-6 as a multi-model PDB file, the first model alone,
    and every atom's coordinates per model (frames, atoms, 3)."""
    tmp = tmp_path_factory.mktemp("track")
    models, xyz = [], []
    with gzip.open(DATA / "1l2y.pdb.gz", "rt") as f:
        for line in f:
            if line.startswith("MODEL"):
                if int(line.split()[1]) == 7:
                    break
                models.append([])
                xyz.append([])
            if line.startswith(("ATOM", "TER")):
                models[-1].append(line)
            if line.startswith("ATOM"):
                xyz[-1].append([float(line[30:38]), float(line[38:46]), float(line[46:54])])
    (tmp / "m6.pdb").write_text("".join(f"MODEL     {k + 1:4d}\n" + "".join(m) + "ENDMDL\n" for k, m in enumerate(models)))
    (tmp / "m1.pdb").write_text("".join(models[0]) + "END\n")
    return tmp, np.array(xyz)


def cli_files(tmp, name, *args):
    cli("track", tmp / "m6.pdb", *args, "-o", tmp / name)
    return {f: (tmp / name / f).read_text() for f in COMPARED}


def test_arrays_give_the_cli_files(ensemble):
    tmp, xyz = ensemble
    assert xyz.shape == (6, 304, 3)
    result = alphapocket.track(xyz, topology=tmp / "m1.pdb")
    expected = cli_files(tmp, "cli")
    for name in COMPARED:
        assert result.files[name] == expected[name], name
    # The parsed tables and grids are those files.
    assert len(result.frames) == expected["frames.csv"].count("\n") - 1 > 0
    assert {r["frame"] for r in result.frames} <= set(range(6))
    assert len(result.tracks) == expected["tracks.csv"].count("\n") - 1
    assert result.frequency.shape == result.density.shape and result.frequency.ndim == 3
    assert set(np.unique(result.frequency * 6).round(4)) <= {float(k) for k in range(7)}
    first = min(r["frame"] for r in result.frames if r["kind"] == "pocket")
    assert result.frequency.max() > 0 and first == 1  # model 1 has no pocket (the CLI says so too)


def test_frames_taken_as_the_cli_takes_them(ensemble):
    tmp, xyz = ensemble
    result = alphapocket.track(xyz, topology=tmp / "m1.pdb", begin=1, stride=2, threads=2)
    expected = cli_files(tmp, "strided", "--begin", "1", "--stride", "2")
    assert result.files["frames.csv"] == expected["frames.csv"]
    assert result.files["tracks.csv"] == expected["tracks.csv"]
    assert {r["frame"] for r in result.frames} <= {1, 3, 5}


def test_times_given(ensemble):
    tmp, xyz = ensemble
    result = alphapocket.track(xyz, topology=tmp / "m1.pdb", times=[0.5 * k for k in range(6)])
    assert result.frames and all(r["time"] == 0.5 * r["frame"] for r in result.frames)


def test_universe_gives_the_cli_files(ensemble):
    mda = pytest.importorskip("MDAnalysis")
    tmp, _ = ensemble
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        universe = mda.Universe(str(tmp / "m6.pdb"))
    assert universe.trajectory.n_frames == 6
    result = alphapocket.track(universe)
    expected = cli_files(tmp, "cli_u")
    # MDAnalysis holds float32 coordinates: every number within the last
    # printed digit, the rest (frames, kinds, tracks, ranks, residues) equal.
    for name in ("frames.csv", "tracks.csv"):
        assert_close_tables(result.files[name], expected[name])
    assert result.files["events.csv"] == expected["events.csv"]
    written = result.write(tmp / "written")
    assert set(written) >= set(COMPARED) and (tmp / "written" / "tracks.csv").read_text() == result.files["tracks.csv"]


def assert_close_tables(got, expected):
    got, expected = [list(csv.reader(io.StringIO(t))) for t in (got, expected)]
    assert len(got) == len(expected) > 1
    for a, b in zip(got, expected):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            try:
                assert abs(float(x) - float(y)) <= 1.5e-3, (a, b)
            except ValueError:
                assert x == y, (a, b)


def test_bad_frames(ensemble):
    tmp, xyz = ensemble
    with pytest.raises(alphapocket.BadInputError, match="frame 0 has 300 atoms, but the topology has 304"):
        alphapocket.track(xyz[:, :300], topology=tmp / "m1.pdb")
    with pytest.raises(alphapocket.MisuseError, match="unknown option"):
        alphapocket.track(xyz, topology=tmp / "m1.pdb", strides=2)
    with pytest.raises(alphapocket.MisuseError, match="topology"):
        alphapocket.track(xyz)
    with pytest.raises(alphapocket.MisuseError, match="3 times for 6 frames"):
        alphapocket.track(xyz, topology=tmp / "m1.pdb", times=[0, 1, 2])
    with pytest.raises(alphapocket.BadInputError, match="no such file"):
        alphapocket.track(xyz, topology=tmp / "missing.pdb")
