# SPDX-License-Identifier: Apache-2.0
# The README's "Use from Python" examples and examples/python/ run.
import re
import subprocess
import sys

from conftest import PDB, ROOT


def readme_blocks(section):
    text = (ROOT / "README.md").read_text()
    body = text.split("## " + section + "\n", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", body, re.S)


def test_readme_python_examples(tmp_path, monkeypatch):
    blocks = readme_blocks("Use from Python")
    assert len(blocks) == 2
    monkeypatch.chdir(tmp_path)
    (tmp_path / "examples" / "data").mkdir(parents=True)
    (tmp_path / "examples" / "data" / "1a26A.pdb").write_bytes(PDB.read_bytes())
    for block in blocks:
        exec(compile(block, "README.md", "exec"), {})
    assert (tmp_path / "1a26A_pockets" / "report.json").is_file()


def test_sites_csv_example(tmp_path):
    out = tmp_path / "sites.csv"
    subprocess.run([sys.executable, ROOT / "examples" / "python" / "sites_csv.py", PDB, out], check=True)
    rows = out.read_text().splitlines()
    assert rows[0].startswith("rank,kind,probability,score,sa_volume")
    assert len(rows) > 5
    rank, kind, probability, score = rows[1].split(",")[:4]
    assert rank == "1" and kind in ("pocket", "void") and 0 < float(probability) <= 1 and float(score) > 0
    probabilities = [float(row.split(",")[2]) for row in rows[1:]]
    assert probabilities == sorted(probabilities, reverse=True)


def test_persistence_example():
    r = subprocess.run([sys.executable, ROOT / "examples" / "python" / "point_cloud_persistence.py"],
                       check=True, capture_output=True, text=True)
    assert "Betti numbers 1 2 1 from alpha_sq" in r.stdout
