# SPDX-License-Identifier: Apache-2.0
# Bad input raises the documented exception types with the CLI's messages.
import numpy as np
import pytest

import alphapocket
from conftest import DATA, cli


def cli_message(*args, code=1):
    r = cli(*args, check=False)
    assert r.returncode == code
    return r.stderr.strip().removeprefix("ERROR: ")


@pytest.mark.parametrize("name", ["missing.pdb", "bad/corrupt.pdb.gz", "bad/three_atoms.pdb"])
def test_bad_files(name, tmp_path):
    path = DATA / name
    with pytest.raises(alphapocket.BadInputError) as e:
        alphapocket.analyze(path)
    assert str(e.value) == cli_message("pockets", path, "-o", tmp_path / "out", "-q")
    assert isinstance(e.value, alphapocket.Error)


def test_input_size_limit(tmp_path):
    """A file above max_input_mb is a limit exceeded (the CLI's exit 5)."""
    big = tmp_path / "big.pdb"
    big.write_bytes(b" " * (3 << 20))
    message = cli_message("surface", big, "--max-input-mb", "2", code=5)
    assert "more than the limit for a structure file of 2 MiB" in message
    with pytest.raises(alphapocket.LimitExceededError) as e:
        alphapocket.surface(big, max_input_mb=2)
    assert str(e.value) == message
    with pytest.raises(alphapocket.LimitExceededError) as e:
        alphapocket.analyze(big, max_input_mb=2)
    assert str(e.value) == message
    with pytest.raises(alphapocket.MisuseError):
        alphapocket.analyze(big, max_input_mb=0)


def test_coplanar_atoms():
    xyz = np.array([[x, y, 0.0] for x in range(5) for y in range(5)]) * 3
    with pytest.raises(alphapocket.BadInputError, match="coplanar"):
        alphapocket.analyze(coordinates=xyz, radii=np.full(len(xyz), 1.7))


def test_misuse():
    with pytest.raises(alphapocket.MisuseError):
        alphapocket.AlphaComplex(np.zeros((4, 2)))
    with pytest.raises(alphapocket.MisuseError):
        alphapocket.AlphaComplex(np.eye(4, 3), weights=[1.0])
    with pytest.raises(alphapocket.MisuseError):
        alphapocket.analyze(DATA / "1fkgA.pdb", no_such_option=1)
    with pytest.raises(alphapocket.MisuseError):
        alphapocket.analyze(coordinates=np.eye(5, 3), radii=[1.0])
    with pytest.raises(alphapocket.MisuseError, match="unknown output 'reports'"):
        alphapocket.analyze(DATA / "1fkgA.pdb", outputs="reports")
    with pytest.raises(alphapocket.MisuseError, match="not a residue code"):
        alphapocket.analyze(DATA / "1fkgA.pdb", keep_hetero="ZN,H E M")
    with pytest.raises(alphapocket.MisuseError, match="ranking"):
        alphapocket.analyze(DATA / "1fkgA.pdb", ranking="best")
    with pytest.raises(alphapocket.MisuseError):
        alphapocket.surface(coordinates=[[0, 0, 0]], radii=[1.0], probe=-1)


def test_non_finite_point():
    with pytest.raises(alphapocket.BadInputError, match="not a finite number"):
        alphapocket.AlphaComplex([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, float("nan")]])
