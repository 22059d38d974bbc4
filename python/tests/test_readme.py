# SPDX-License-Identifier: Apache-2.0
# The Python examples run: README's, docs/library.md's "Use from Python"
# and examples/python/.
import re
import subprocess
import sys

import alphapocket
from conftest import DATA, PDB, ROOT


def python_blocks(document, section):
    text = (ROOT / document).read_text()
    body = text.split("## " + section + "\n", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", body, re.S)


def run_blocks(document, blocks, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "examples" / "data").mkdir(parents=True)
    (tmp_path / "examples" / "data" / "1a26A.pdb").write_bytes(PDB.read_bytes())
    (tmp_path / "tests" / "data").mkdir(parents=True)
    (tmp_path / "tests" / "data" / "1l2y.pdb.gz").write_bytes((DATA / "1l2y.pdb.gz").read_bytes())
    for block in blocks:
        exec(compile(block, document, "exec"), {})
    assert (tmp_path / "1a26A_pockets" / "report.json").is_file()


def test_library_python_examples(tmp_path, monkeypatch):
    blocks = python_blocks("docs/library.md", "Use from Python")
    assert len(blocks) == 3
    run_blocks("docs/library.md", blocks, tmp_path, monkeypatch)
    assert (tmp_path / "1l2y_track" / "tracks.csv").is_file()


def test_readme_python_example(tmp_path, monkeypatch):
    blocks = python_blocks("README.md", "Use it")
    assert len(blocks) == 1
    run_blocks("README.md", blocks, tmp_path, monkeypatch)


def test_sites_csv_example(tmp_path):
    out = tmp_path / "sites.csv"
    subprocess.run([sys.executable, ROOT / "examples" / "python" / "sites_csv.py", PDB, out], check=True)
    rows = out.read_text().splitlines()
    assert rows[0].startswith("rank,kind,probability,score,sa_volume")
    # One row per site of the same analysis, in rank order.
    sites = alphapocket.analyze(PDB, tunnels_from="none").sites
    assert len(sites) >= 3
    assert [row.split(",")[0] for row in rows[1:]] == [str(site.rank) for site in sites]
    rank, kind, probability, score = rows[1].split(",")[:4]
    assert rank == "1" and kind in ("pocket", "void") and 0 < float(probability) <= 1 and float(score) > 0
    probabilities = [float(row.split(",")[2]) for row in rows[1:]]
    assert probabilities == sorted(probabilities, reverse=True)


def test_persistence_example():
    r = subprocess.run([sys.executable, ROOT / "examples" / "python" / "point_cloud_persistence.py"],
                       check=True, capture_output=True, text=True)
    assert "Betti numbers 1 2 1 from alpha_sq" in r.stdout
