# SPDX-License-Identifier: Apache-2.0
# analyze(): the report and files of `alphapocket pockets`, from a path,
# from arrays and from a gemmi structure.
import filecmp
import json
import re

import numpy as np
import pytest

import alphapocket
from conftest import DATA, PDB, cli


def test_to_json_equals_report_json(pdb_analysis, tmp_path):
    cli("pockets", PDB, "-o", tmp_path / "cli", "-q")
    assert pdb_analysis.to_json() == (tmp_path / "cli" / "report.json").read_text()


def test_write_equals_cli_files(pdb_analysis, tmp_path):
    # The outputs write() writes; the CLI's default adds report.html when Mol* is installed.
    cli("pockets", PDB, "-o", tmp_path / "cli", "-q", "--outputs", alphapocket._ANALYZE_DEFAULTS["outputs"])
    written = pdb_analysis.write(tmp_path / "py")
    assert "report.json" in written and "pockets.csv" in written
    cmp = filecmp.dircmp(tmp_path / "cli", tmp_path / "py")
    assert not cmp.left_only and not cmp.right_only and "meshes" not in cmp.common
    assert not filecmp.cmpfiles(tmp_path / "cli", tmp_path / "py", cmp.common_files, shallow=False)[1]


def test_write_all_equals_cli_files(tmp_path):
    """outputs="all" writes the meshes too, as the CLI's --outputs all."""
    cli("pockets", DATA / "1fkgA.pdb", "--outputs", "all", "-o", tmp_path / "cli", "-q")
    alphapocket.analyze(DATA / "1fkgA.pdb", outputs="all").write(tmp_path / "py")
    cmp = filecmp.dircmp(tmp_path / "cli", tmp_path / "py")
    assert not cmp.left_only and not cmp.right_only
    assert not filecmp.cmpfiles(tmp_path / "cli", tmp_path / "py", cmp.common_files, shallow=False)[1]
    meshes = sorted(p.name for p in (tmp_path / "cli" / "meshes").iterdir())
    assert meshes and meshes == sorted(p.name for p in (tmp_path / "py" / "meshes").iterdir())
    for name in meshes:
        assert (tmp_path / "cli" / "meshes" / name).read_bytes() == (tmp_path / "py" / "meshes" / name).read_bytes()


def test_records_follow_the_report(pdb_analysis):
    report = json.loads(pdb_analysis.to_json())
    a = pdb_analysis
    for key in ("sites", "pockets", "voids", "tunnels"):
        assert len(getattr(a, key)) == len(report[key])
    assert len(a.sites) > 0 and len(a.pockets) > 0
    site, first = a.sites[0], report["sites"][0]
    assert site.score == first["score"]
    assert isinstance(site.center, np.ndarray) and site.center.shape == (3,)
    assert np.array_equal(site.center, np.asarray(first["center"]))
    pocket = report["pockets"][first["cavity_rank"] - 1]
    assert site.cavity.ms_volume == pocket["ms_volume"]
    assert site.cavity.lining_residues[0] == tuple(pocket["lining_residues"][0][k]
                                                   for k in ("chain", "name", "number", "insertion_code"))
    assert len(site.cavity.lining_residues) == len(pocket["lining_residues"])
    assert a.tunnels[0].bottleneck_center.shape == (3,)
    assert a.report["molecule"]["atoms"] == 2769


@pytest.mark.parametrize("name, options", [("3stdA.pdb", {}), ("1ytjA.pdb", {}), ("1ytjA.pdb", {"keep_hetero": True}),
                                           ("1pfe.cif.gz", {}), ("1UYD.pdb", {"chains": ["A"]})])
def test_gemmi_structure_equals_the_file(name, options):
    """A gemmi.Structure (written by gemmi as mmCIF, read as a file) gives
    the file's atoms, selection (ligands, waters, altlocs) and results
    (an adapter selecting gemmi's atoms in Python kept 171 of 1pfe's atoms,
    the file 199; gemmi's mmCIF without group_PDB made 1ytjA's ligands
    polymer)."""
    gemmi = pytest.importorskip("gemmi")
    path = DATA / name
    from_file = alphapocket.analyze(path, tunnels_from="none", **options)
    from_gemmi = alphapocket.analyze(gemmi.read_structure(str(path)), tunnels_from="none", **options)
    a, b = from_file.report, from_gemmi.report
    for key in ("atoms_kept", "atoms_dropped", "hetero_groups"):
        assert a["input"][key] == b["input"][key]
    assert b["input"]["file"] == gemmi.read_structure(str(path)).name  # gemmi's name for it
    del a["input"], b["input"]
    # Atom serial numbers are gemmi's: its mmCIF writer numbers the atoms afresh.
    without_serials = lambda report: re.sub(r'"serial": [0-9]+', "", json.dumps(report))
    assert without_serials(a) == without_serials(b) and from_file.sites
    assert alphapocket.surface(path).ms_area == alphapocket.surface(gemmi.read_structure(str(path))).ms_area


def test_arrays_with_radii():
    """Balls on a hollow shell: one void inside, whatever the names."""
    rng = np.random.default_rng(1)
    d = rng.normal(size=(600, 3))
    xyz = 9.0 * d / np.linalg.norm(d, axis=1)[:, None]
    a = alphapocket.analyze(coordinates=xyz, radii=np.full(600, 1.8), tunnels_from="none")
    assert a.report["input"]["file"] == "arrays"
    assert len(a.voids) == 1
    # The void's centre lies near the shell's centre.
    assert np.linalg.norm(a.voids[0].center) < 2.0


def test_options_reach_the_search(pdb_analysis):
    """min_volume drops the smaller cavities (the defaults keep some below
    it); a larger probe gives a larger solvent-accessible volume."""
    a = alphapocket.analyze(PDB, probe=1.6, min_volume=20, tunnels_from="none")
    assert a.report["parameters"]["probe"] == 1.6
    assert a.report["parameters"]["min_volume"] == 20
    default = pdb_analysis.pockets + pdb_analysis.voids
    assert any(c.sa_volume < 20 for c in default)
    assert a.pockets and all(c.sa_volume >= 20 for c in a.pockets + a.voids)
    assert a.report["molecule"]["sa_volume"] > pdb_analysis.report["molecule"]["sa_volume"]


def test_sites_carry_the_ligandability_probability(pdb_analysis):
    """Sites are ranked by the model's rank score (as the CLI's default; the
    features' rank_score column), each with .probability in [0, 1];
    ranking="geometric" orders by score."""
    sites = pdb_analysis.sites
    assert all(0 <= s.probability <= 1 for s in sites)
    columns = pdb_analysis.features()
    by_rank = sorted((r, x) for r, x in zip(columns["site_rank"], columns["rank_score"]) if r > 0)
    assert [r for r, _ in by_rank] == list(range(1, len(sites) + 1))
    assert [x for _, x in by_rank] == sorted((x for _, x in by_rank), reverse=True)
    assert all(s.probability == s.cavity.probability for s in sites)
    geometric = alphapocket.analyze(PDB, ranking="geometric", tunnels_from="none")
    assert [s.score for s in geometric.sites] == sorted((s.score for s in geometric.sites), reverse=True)
    assert [s.score for s in sites] != [s.score for s in geometric.sites]  # the two rankings differ here


def test_features_equal_the_cli_file(pdb_analysis, tmp_path):
    cli("pockets", PDB, "-o", tmp_path / "out", "--features", tmp_path / "features.csv", "-q")
    text = (tmp_path / "features.csv").read_text()
    assert pdb_analysis.features_csv() == text
    columns = pdb_analysis.features()
    n = len(pdb_analysis.pockets) + len(pdb_analysis.voids)
    assert list(columns) == text.splitlines()[0].split(",")
    assert len(columns["kind"]) == n and columns["burial_14"].shape == (n,) and columns["site_rank"].dtype == int
    site = pdb_analysis.sites[0]
    row = [i for i in range(n) if columns["site_rank"][i] == 1][0]
    assert columns["kind"][row] == site.kind and columns["cavity_rank"][row] == site.cavity_rank
    assert columns["probability"][row] == pytest.approx(site.probability, abs=5e-5)


@pytest.mark.parametrize("option, flag", [({"keep_hetero": "zn,CA"}, "--keep-hetero=ZN,CA"),
                                          ({"keep_hetero": ["ZN", "CA"]}, "--keep-hetero=ZN,CA"),
                                          ({"keep_cofactors": True}, "--keep-cofactors")])
def test_hetero_selection_and_ligands(option, flag, tmp_path):
    """keep_hetero with residue codes and keep_cofactors select as the CLI's
    flags do; .ligands are report.json's ligands, each with its site."""
    path = DATA / "1fbl.pdb"  # HTA, 4 Ca, 2 Zn
    cli("pockets", path, flag, "--tunnels-from", "none", "-o", tmp_path / "cli", "-q")
    a = alphapocket.analyze(path, tunnels_from="none", **option)
    assert a.to_json() == (tmp_path / "cli" / "report.json").read_text()
    assert len(a.ligands) == len(a.report["ligands"]) > 0
    assert [vars(x).keys() for x in a.ligands][0] == a.report["ligands"][0].keys()
    assert a.report["input"]["atoms_kept"] > alphapocket.analyze(path, tunnels_from="none").report["input"]["atoms_kept"]
