# SPDX-License-Identifier: Apache-2.0
# The bad-input catalog (tests/cli/catalog.cases) through the module: every
# row of `pockets` and `surface` on a bad input file raises the exception of
# its kind with the message the command line prints (the row's pattern);
# every row the command line accepts passes. No crash on any of them.
import re

import pytest

import alphapocket
from conftest import DATA, ROOT

ERRORS = {1: alphapocket.BadInputError, 5: alphapocket.LimitExceededError}
CALLS = {"pockets": lambda path: alphapocket.analyze(path, tunnels_from="none"),
         "surface": lambda path: alphapocket.surface(path)}


def rows():
    """(id, command, input, exit code, pattern) of the rows about the input
    file alone (OUTDIR new) for pockets and surface."""
    out = []
    for line in (ROOT / "tests" / "cli" / "catalog.cases").read_text().splitlines():
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        ident, commands, path, outdir, code, message = line.split(None, 5)
        if ident.startswith("!") or outdir != "new":
            continue
        for command in commands.split(","):
            for c in (CALLS if command == "all" else [command]):
                if c in CALLS:
                    out.append(pytest.param(c, path, int(code), message, id=f"{ident}.{c}"))
    return out


CASES = rows()


def test_the_catalog_has_rows():
    assert len(CASES) >= 40


@pytest.mark.parametrize("command, path, code, message", CASES)
def test_catalog_row(command, path, code, message, tmp_path):
    if path == "@missing":
        path = str(tmp_path / "missing.pdb")
    elif path == "@dir":
        path = str(tmp_path / "dir.pdb")
        (tmp_path / "dir.pdb").mkdir()
    else:
        path = str(DATA / path)
    if code == 0:
        CALLS[command](path)
        return
    with pytest.raises(ERRORS[code]) as e:
        CALLS[command](path)
    pattern = message.replace("{IN}", re.escape(path))
    assert re.fullmatch(pattern, str(e.value)), (str(e.value), pattern)
