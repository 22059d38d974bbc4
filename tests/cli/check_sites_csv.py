#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""sites.csv of `alphapocket pockets` read back and checked against
report.json: one row per site (pockets and voids), in rank order, each
value equal to the report's.

    check_sites_csv.py OUTDIR STRUCTURE_ID   exits 1 naming the first difference
"""
import csv
import json
import os
import sys

outdir, structure_id = sys.argv[1:3]


def fail(message):
    print(f"FAIL: sites.csv: {message}", file=sys.stderr)
    sys.exit(1)


with open(os.path.join(outdir, "report.json")) as f:
    report = json.load(f)
with open(os.path.join(outdir, "sites.csv"), newline="") as f:
    rows = list(csv.DictReader(f))
sites = report["sites"]
if len(rows) != len(sites):
    fail(f"{len(rows)} rows, report.json has {len(sites)} sites")
if not any(s["kind"] == "void" for s in sites):
    fail("the test needs a structure with a void among its sites")
for row, site in zip(rows, sites):
    cavity = report[site["kind"] + "s"][site["cavity_rank"] - 1]
    expected = {
        "structure_id": structure_id, "site_rank": site["rank"], "kind": site["kind"],
        "cavity_rank": site["cavity_rank"], "score": cavity["score"], "sa_volume": cavity["sa_volume"],
        "ms_volume": cavity["ms_volume"], "sa_area": cavity["sa_area"], "ms_area": cavity["ms_area"],
        "depth": cavity["depth"], "mouths": cavity["mouths"], "mouth_area": cavity["mouth_area"],
        "center_x": site["center"][0], "center_y": site["center"][1], "center_z": site["center"][2],
        "lining_residues": len(site["lining_residues"]),
        "residues": " ".join(r["id"] for r in site["lining_residues"]),
        "ligands": " ".join(site["ligands"]),
    }
    for key, value in expected.items():
        got = row.get(key)
        same = got == value if isinstance(value, str) else got not in (None, "") and float(got) == value
        if not same:
            fail(f"site {site['rank']}: {key} is {got!r}, report.json has {value!r}")
    if [r["id"] for r in site["lining_residues"]] != [r["id"] for r in cavity["lining_residues"]]:
        fail(f"site {site['rank']}: sites[].lining_residues differ from its {site['kind']}'s")
print(f"sites.csv: {len(rows)} rows ({sum(s['kind'] == 'void' for s in sites)} voids) as in report.json")
