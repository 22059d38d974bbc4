# SPDX-License-Identifier: Apache-2.0
# Shared fixtures: the alphapocket binary and the repository (set by CTest).
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(os.environ.get("ALPHAPOCKET_ROOT", Path(__file__).resolve().parents[2]))
EXE = os.environ.get("ALPHAPOCKET_EXE", str(ROOT / "build" / "apps" / "alphapocket"))
PDB = ROOT / "examples" / "data" / "1a26A.pdb"  # PDB 1A26 chain A, 2.7k atoms
SMALL = ROOT / "tests" / "data" / "1grm_single.pdb"  # gramicidin A, 272 atoms
DATA = ROOT / "tests" / "data"


def cli(*args, check=True):
    """Runs the alphapocket binary; returns the CompletedProcess."""
    return subprocess.run([EXE, *map(str, args)], capture_output=True, text=True, check=check)


@pytest.fixture(scope="session")
def pdb_analysis():
    import alphapocket
    return alphapocket.analyze(str(PDB))
